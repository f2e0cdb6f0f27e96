#pragma once
// How a step's work is split between the members of the thread team (core/thread_team.hpp):
// every node belongs to one member, which alone writes it (its force, velocity and position,
// its ground contact history), and each member evaluates every spring that has a node of its
// own, adding the spring's forces to its own nodes only. A spring between two members' nodes is
// evaluated by both (each keeps its part), which costs a little work at the border and saves
// every barrier: no two members ever write to one node, so the threads meet once a step, before
// they move the nodes (the wind's drag adds a meeting, turbulence another). Each node still
// receives its forces in one fixed order — kind by kind, springs in id order — whoever computes
// them, so the motion is the same bit for bit on 1 thread or 16.
//
// A member owns a contiguous range of node ids, cut at multiples of kNodeGrain: each member
// writes its own stretch of every node array, so no cache line is written by two (a split of
// the nodes in space, across a row-ordered grid, put every row's middle node pair in one cache
// line, and the two threads' many additions to those forces made a step 1.4× slower than one
// thread's share). Meshes are numbered along their surface (grids by rows, modelling tools and
// scanners by patches), so a range of ids is a compact piece of the structure and few springs
// cross between pieces; a member's springs then fall in a few long runs of consecutive ids,
// which its loops take as the whole model is taken on one thread.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

// Node ranges start at multiples of this many nodes (8 positions or forces are 3 cache lines).
inline constexpr Index kNodeGrain = 8;

// Consecutive spring ids [first, first + count).
struct SpringRun {
  Index first = 0;
  Index count = 0;
};

// One member's part of the work.
struct MemberShare {
  Index first_node = 0;  // it owns the nodes [first_node, end_node)
  Index end_node = 0;
  std::vector<SpringRun> bars;      // bars with an end among them (axial springs and dampers)
  std::vector<SpringRun> bends;     // bending springs with a node among them
  std::vector<SpringRun> torsions;  // torsion springs with a node among them

  bool owns(Index node) const { return node >= first_node && node < end_node; }
};

struct WorkSplit {
  int members = 0;                  // the team size it was made for; 0: not made
  std::vector<MemberShare> shares;  // (members)
  Index shared_springs = 0;         // springs evaluated by more than one member
};

// The split of `model`'s nodes and springs between `members` members.
WorkSplit split_work(const Model& model, int members);

}  // namespace dinam
