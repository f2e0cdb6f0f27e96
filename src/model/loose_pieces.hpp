#pragma once
// Meshes as they come from the web are often several separate pieces: a model's eyes, teeth or
// buckles are their own shells, touching the body but sharing no vertex with it. Each becomes a
// piece of structure that no bar joins to the rest, and it falls away from the body as soon as
// the motion starts. That is told as a note at the object's mesh, the run goes on.
#include "scene/scene_description.hpp"

namespace dinam {

struct Model;

// Adds to model.warnings, for each object whose bars make more than one connected piece and some
// piece of which holds no pinned node: how many pieces, how large the largest, how many move
// free, and what would hold them.
void note_loose_pieces(const SceneDescription& scene, Model& model);

}  // namespace dinam
