#pragma once
// Contact where objects are tied (`attach`): a rope's end tied on its hook touches the hook, and
// a tie's loop around a pole passes through it between its tied nodes, from the start. Those
// pairs would push the tied parts apart with energy from nowhere, so they are left out, as a
// mesh's neighbours are; every other pair of the two objects keeps its contact, so the rest of a
// flag still cannot pass through its pole, nor a tied node's other bars.

namespace dinam {

struct Model;

// Fills model.contact's tied_bar_pairs and tied_point_triangles: the pairs between a tied node's
// bars (or faces) and its target's bars (or faces, or nodes) that touch at the start (nearer
// than the sum of their radii). Needs the contact's radii and triangles.
void leave_out_pairs_tied_at_rest(Model& model);

}  // namespace dinam
