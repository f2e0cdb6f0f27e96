#pragma once
// Spring forces in blocks of one colour (parallel_loops.hpp), in three passes per block:
//   1. gather: copy each spring's node positions and parameters into the block, one array per
//      quantity (structure of arrays);
//   2. compute: run the spring's kernel on every spring of the block, one spring per SIMD lane;
//      the loop reads and writes only the block's arrays, without branches, so it vectorises;
//   3. scatter: add the forces to the nodes and keep the plastic flow.
// Passes 1 and 3 are scalar loads and stores through the node ids; pass 2, where the arithmetic
// is, would not vectorise with them inside (the compiler cannot gather through two levels of
// indices, nor scatter to nodes).
#include <limits>
#include <vector>

#include "core/types.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/parallel_loops.hpp"

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
};

template <int kNodes>
struct SpringBlock {
  // Inputs, gathered: position[j][axis][k] is the position of node j (in the spring's node
  // order) of the block's spring k.
  double position[kNodes][3][kSpringBlockSize];
  double rest[kSpringBlockSize];
  double stiffness[kSpringBlockSize];
  double yield[kSpringBlockSize];
  double plastic_set[kSpringBlockSize];
  // Outputs: the force on each node, the plastic set after this evaluation and the work its
  // flow dissipated (J).
  double force[kNodes][3][kSpringBlockSize];
  double new_plastic_set[kSpringBlockSize];
  double dissipated[kSpringBlockSize];

  Vec3 node_position(int node, Index k) const {
    return {position[node][0][k], position[node][1][k], position[node][2][k]};
  }
  void set_force(int node, Index k, const Vec3& f) {
    force[node][0][k] = f.x();
    force[node][1][k] = f.y();
    force[node][2][k] = f.z();
  }
  Vec3 node_force(int node, Index k) const {
    return {force[node][0][k], force[node][1][k], force[node][2][k]};
  }
};

// Pass 2: kernel(block, k, plastic_set, yield) for k in [0, count). The kernel must be a lambda
// without captures (everything it needs is in the block) and must not branch, or the loop will
// not vectorise. For a kind that cannot yield, every plastic set stays 0: the kernel then gets
// the constants 0 and ∞, and the compiler drops the plastic branch of elastoplastic() with its
// division.
template <int kNodes, class Kernel>
void compute_spring_block(SpringBlock<kNodes>& block, Index count, bool may_yield,
                          const Kernel& kernel) {
  if (may_yield) {
#pragma omp simd
    for (Index k = 0; k < count; ++k) {
      kernel(block, k, block.plastic_set[k], block.yield[k]);
    }
  } else {
    constexpr double kElastic = std::numeric_limits<double>::infinity();
#pragma omp simd
    for (Index k = 0; k < count; ++k) {
      kernel(block, k, 0.0, kElastic);
    }
  }
}

// Adds the forces of every spring of one kind to context.force, colour by colour, and keeps the
// plastic flow when the context advances history.
template <int kNodes, class Kernel>
void add_spring_forces(ForceContext& context, const SpringArrays& springs, const Kernel& kernel) {
  const bool may_yield = springs.colouring.any_yield;
  const Vec3* x = context.state.x.data();
  Vec3* force = context.force.data();
  const Index* spring_nodes = springs.nodes.data();
  for_each_spring_block(springs.colouring, [&](const Index* ids, Index count) {
    SpringBlock<kNodes> block;
    for (Index k = 0; k < count; ++k) {
      const Index s = ids[k];
      const Index* nodes = &spring_nodes[static_cast<std::size_t>(kNodes) * s];
      for (int j = 0; j < kNodes; ++j) {
        const Vec3& p = x[nodes[j]];
        block.position[j][0][k] = p.x();
        block.position[j][1][k] = p.y();
        block.position[j][2][k] = p.z();
      }
      block.rest[k] = springs.rest[s];
      block.stiffness[k] = springs.stiffness[s];
    }
    if (may_yield) {
      for (Index k = 0; k < count; ++k) {
        block.yield[k] = springs.yield[ids[k]];
        block.plastic_set[k] = springs.plastic_set[ids[k]];
      }
    }
    compute_spring_block(block, count, may_yield, kernel);
    for (Index k = 0; k < count; ++k) {
      const Index* nodes = &spring_nodes[static_cast<std::size_t>(kNodes) * ids[k]];
      for (int j = 0; j < kNodes; ++j) {
        force[nodes[j]] += block.node_force(j, k);
      }
    }
    if (may_yield) {
      for (Index k = 0; k < count; ++k) {
        context.record_plastic_flow(ids[k], springs.plastic_set[ids[k]], block.new_plastic_set[k],
                                    block.dissipated[k]);
      }
    }
  });
  context.book_plastic_flow(springs.colouring);
}

}  // namespace dinam
