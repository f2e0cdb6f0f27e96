#pragma once
// Spring forces by blocks of consecutive springs (model/spring_colouring.hpp), in three passes
// per block:
//   1. gather: copy each spring's node positions into the block, one array per coordinate of
//      each node (structure of arrays);
//   2. compute: run the spring's kernel on every spring of the block, one spring per SIMD lane;
//      the loop reads and writes only the block's arrays, without branches, so it vectorises;
//   3. scatter: add the forces to the nodes and keep the plastic flow.
// Passes 1 and 3 are scalar loads and stores through the node ids; pass 2, where the arithmetic
// is, would not vectorise with them inside (the compiler cannot scatter to the nodes, and the
// x86-64 baseline has no gather either).
#include <cstdint>
#include <limits>
#include <vector>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/vector_lanes.hpp"

namespace dinam {

// One kind of elastoplastic spring as the model and state hold it: kNodes node ids per spring,
// and one value per spring of each parameter.
struct SpringArrays {
  const SpringColouring& colouring;
  const std::vector<Index>& nodes;       // (n_springs × kNodes)
  const std::vector<double>& rest;       // (n_springs) m or rad
  const std::vector<double>& stiffness;  // (n_springs) N/m or N·m/rad
  const std::vector<double>& yield;      // (n_springs) N or N·m; infinite when elastic
  std::vector<double>& plastic_set;      // (n_springs) m or rad
  const std::uint8_t* broken = nullptr;  // (n_springs) 1 for a torn spring; null: none can tear
};

// The broken flags of one kind of spring, or null when the model cannot tear.
inline const std::uint8_t* broken_flags(const std::vector<std::uint8_t>& flags) {
  return flags.empty() ? nullptr : flags.data();
}

template <int kNodes>
struct SpringBlock {
  // Inputs, gathered: position[j] holds node j's position (in the spring's node order) for each
  // of the block's springs.
  Vec3Lanes<kSpringBlockSize> position[kNodes];
  // Outputs: the force on each node, the plastic set after this evaluation and the work its
  // flow dissipated (J).
  Vec3Lanes<kSpringBlockSize> force[kNodes];
  double new_plastic_set[kSpringBlockSize];
  double dissipated[kSpringBlockSize];

  Vec3 node_position(int node, Index k) const { return position[node].get(k); }
  void set_force(int node, Index k, const Vec3& f) { force[node].set(k, f); }
  Vec3 node_force(int node, Index k) const { return force[node].get(k); }
};

// Pass 2: kernel(block, k, rest, stiffness, plastic_set, yield) for the block's springs k in
// [0, count), whose parameters it reads straight from the (contiguous) model and state arrays.
// The kernel must be a lambda without captures and must not branch, or the loop will not
// vectorise. For a kind that cannot yield, every plastic set stays 0: the kernel then gets the
// constants 0 and ∞, and the compiler drops the plastic branch of elastoplastic() with its
// division.
template <int kNodes, class Kernel>
void compute_spring_block(SpringBlock<kNodes>& block, const SpringArrays& springs, Index first,
                          Index count, const Kernel& kernel) {
  const double* rest = springs.rest.data() + first;
  const double* stiffness = springs.stiffness.data() + first;
  if (springs.colouring.any_yield) {
    const double* plastic_set = springs.plastic_set.data() + first;
    const double* yield = springs.yield.data() + first;
#pragma omp simd
    for (Index k = 0; k < count; ++k) {
      kernel(block, k, rest[k], stiffness[k], plastic_set[k], yield[k]);
    }
  } else {
    constexpr double kElastic = std::numeric_limits<double>::infinity();
#pragma omp simd
    for (Index k = 0; k < count; ++k) {
      kernel(block, k, rest[k], stiffness[k], 0.0, kElastic);
    }
  }
}

// Adds the forces of every spring of one kind to context.force, block by block in the colouring's
// order, and keeps the plastic flow when the context advances history.
template <int kNodes, class Kernel>
void add_spring_forces(ForceContext& context, const SpringArrays& springs, const Kernel& kernel) {
  const bool may_yield = springs.colouring.any_yield;
  const Vec3* x = context.state.x.data();
  Vec3* force = context.force.data();
  for_each_spring_block(springs.colouring, [&](Index first, Index count) {
    const Index* spring_nodes = &springs.nodes[static_cast<std::size_t>(kNodes) * first];
    SpringBlock<kNodes> block;
    for (Index k = 0; k < count; ++k) {
      for (int j = 0; j < kNodes; ++j) {
        block.position[j].set(k, x[spring_nodes[kNodes * k + j]]);
      }
    }
    compute_spring_block(block, springs, first, count, kernel);
    const std::uint8_t* broken = springs.broken == nullptr ? nullptr : springs.broken + first;
    for (Index k = 0; k < count; ++k) {
      if (broken != nullptr && broken[k] != 0) {
        continue;  // torn: computed with the block, but it acts no more
      }
      for (int j = 0; j < kNodes; ++j) {
        force[spring_nodes[kNodes * k + j]] += block.node_force(j, k);
      }
    }
    if (may_yield && context.update_history) {
      // The new plastic sets, and the flow's work summed in four interleaved partial sums (a
      // fixed order, which the compiler may keep in one vector register).
      double* plastic_set = &springs.plastic_set[first];
      double partial[4] = {0.0, 0.0, 0.0, 0.0};
      for (Index k = 0; k < count; ++k) {
        const bool acts = broken == nullptr || broken[k] == 0;
        plastic_set[k] = acts ? block.new_plastic_set[k] : plastic_set[k];
        partial[k & 3] += acts ? block.dissipated[k] : 0.0;
      }
      context.record_plastic_flow(first / kSpringBlockSize,
                                  (partial[0] + partial[1]) + (partial[2] + partial[3]));
    }
  });
  context.book_plastic_flow(springs.colouring);
}

}  // namespace dinam
