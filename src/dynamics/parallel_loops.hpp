#pragma once
// How the members of the thread team (core/thread_team.hpp) share a step's loops without
// changing a bit of the result (work_split.hpp):
//  - node loops: each member takes the range of nodes it owns, the same in every node loop of a
//    step and of the next, so node loops follow one another without meeting;
//  - spring loops: each member evaluates the springs with a node of its own, in spring order,
//    and adds their forces to its own nodes only;
//  - item loops into arrays of their own (the wind's drag on faces and bars): each member a
//    share, then a barrier before anyone reads them.
// Called on one thread (no split), every loop runs whole, in the same order.
#include <algorithm>
#include <utility>

#include "core/thread_team.hpp"
#include "core/types.hpp"
#include "dynamics/work_split.hpp"

namespace dinam {

// A step shares its work between the threads only where it has at least this many springs:
// below it, waking the team costs more than the threads save (bench_threads).
inline constexpr Index kMinParallelItems = 4096;

// One thread's place in a step: its member of the team and, when the team shares the work, the
// split that says what is its own.
struct Worker {
  TeamMember member = solo_member();
  const WorkSplit* split = nullptr;  // null: this thread does all the work

  const MemberShare* share() const {
    return split == nullptr ? nullptr : &split->shares[static_cast<std::size_t>(member.index())];
  }
  // Whether it writes the node (its force, velocity, position and history).
  bool owns(Index node) const {
    const MemberShare* own = share();
    return own == nullptr || own->owns(node);
  }
  // The nodes it writes: [first, last).
  std::pair<Index, Index> own_nodes(Index node_count) const {
    const MemberShare* own = share();
    return own == nullptr ? std::pair<Index, Index>{0, node_count}
                          : std::pair<Index, Index>{own->first_node, own->end_node};
  }
};

// body(i) for every node the worker owns, ascending.
template <class Body>
void for_each_own_node(const Worker& worker, Index node_count, const Body& body) {
  const auto [first, last] = worker.own_nodes(node_count);
  for (Index i = first; i < last; ++i) {
    body(i);
  }
}

// body(first, size) for the nodes the worker owns, ascending, `chunk` at a time: for loops that
// gather a few nodes, compute them in SIMD lanes and store them (the ground).
template <class Body>
void for_each_own_node_chunk(const Worker& worker, Index node_count, Index chunk,
                             const Body& body) {
  const auto [first, last] = worker.own_nodes(node_count);
  for (Index i = first; i < last; i += chunk) {
    body(i, std::min(chunk, last - i));
  }
}

// body(first, size) for the springs of one kind that the worker evaluates, in spring order,
// `chunk` at a time, [first, first + size) each: its runs of the kind (`runs`, a member of
// MemberShare), or on one thread all `count` springs.
template <class Body>
void for_each_spring_chunk(const Worker& worker, std::vector<SpringRun> MemberShare::*runs,
                           Index count, Index chunk, const Body& body) {
  auto run = [&](const SpringRun& springs) {
    const Index end = springs.first + springs.count;
    for (Index first = springs.first; first < end; first += chunk) {
      body(first, std::min(chunk, end - first));
    }
  };
  if (const MemberShare* share = worker.share()) {
    for (const SpringRun& springs : share->*runs) {
      run(springs);
    }
    return;
  }
  run({0, count});
}

// body(first, size) for the member's share of the blocks [first, first + size) of at most
// `block_size` items that cover [0, count), each block writing only data of its own: the wind's
// nodes, faces and bars. The blocks do not depend on the thread count, so neither does anything
// computed in them. No barrier: the caller meets the others before it reads what they wrote.
template <class Body>
void for_each_block_share(const TeamMember& member, Index count, Index block_size,
                          const Body& body) {
  const Index blocks = (count + block_size - 1) / block_size;
  const auto [begin, end] = member.share(blocks);
  for (Index b = begin; b < end; ++b) {
    const Index first = b * block_size;
    body(first, std::min(block_size, count - first));
  }
}

// What the leader alone must do, between barriers: body() on member 0, then every member waits
// for it.
template <class Body>
void on_leader(const TeamMember& member, const Body& body) {
  if (member.leader()) {
    body();
  }
  member.barrier();
}

}  // namespace dinam
