#pragma once
// Spring forces by blocks of springs, in three passes per block:
//   1. gather: copy each spring's node positions and parameters into the block, one array per
//      coordinate of each node (structure of arrays);
//   2. compute: run the spring's kernel on every spring of the block, one spring per SIMD lane;
//      the loop reads and writes only the block's arrays, without branches, so it vectorises;
//   3. scatter: add the forces to the nodes (a worker of a team, to its own nodes only) and keep
//      the plastic sets.
// Passes 1 and 3 are scalar loads and stores through the node ids; pass 2, where the arithmetic
// is, would not vectorise with them inside (the compiler cannot scatter to the nodes, and the
// x86-64 baseline has no gather either).
#include <cstdint>
#include <limits>
#include <vector>

#include "core/types.hpp"
#include "dynamics/broken.hpp"
#include "dynamics/force_context.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/vector_lanes.hpp"

namespace dinam {

// One kind of elastoplastic spring as the model and state hold it: kNodes node ids per spring,
// and one value per spring of each parameter.
struct SpringArrays {
  Index count = 0;
  bool any_yield = false;                           // some spring of this kind can flow plastically
  std::vector<SpringRun> MemberShare::*share_runs;  // a worker's springs of this kind
  const std::vector<Index>& nodes;                  // (n_springs × kNodes)
  const std::vector<double>& rest;                  // (n_springs) m or rad
  const std::vector<double>& stiffness;             // (n_springs) N/m or N·m/rad
  const std::vector<double>& yield;                 // (n_springs) N or N·m; infinite when elastic
  std::vector<double>& plastic_set;                 // (n_springs) m or rad
  const std::uint8_t* broken = nullptr;  // (n_springs) 1 for a torn spring; null: none can tear
  std::vector<double>* flow = nullptr;   // (n_springs) J dissipated, while the energy is tracked
};

// Springs per block. A block's gathered inputs and its results stay in the first-level cache
// between the passes over it.
inline constexpr Index kSpringBlockSize = 64;

// Where a kind's springs record the work of their flow: its array while the energy is tracked and
// the context advances history (the array is empty for a kind that cannot yield); null otherwise.
inline std::vector<double>* flow_record(const ForceContext& context, std::vector<double>& flow) {
  return context.update_history && !flow.empty() ? &flow : nullptr;
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
};

// Pass 2: kernel(block, k, rest, stiffness, plastic_set, yield) for the block's springs k in
// [0, count), the springs [first, first + count), whose parameters it reads straight from the
// (contiguous) model and state arrays. The kernel must be a lambda without captures and must not
// branch, or the loop will not vectorise. For a kind that cannot yield, every plastic set stays
// 0: the kernel then gets the constants 0 and ∞, and the compiler drops the plastic branch of
// elastoplastic() with its division.
template <int kNodes, class Kernel>
void compute_spring_block(SpringBlock<kNodes>& block, const SpringArrays& springs, Index first,
                          Index count, const Kernel& kernel) {
  const double* rest = springs.rest.data() + first;
  const double* stiffness = springs.stiffness.data() + first;
  if (springs.any_yield) {
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

// Pass 3's forces: each spring's force on each node, added to the nodes in [own_first, own_end)
// in spring order (a torn spring is computed with the block, but it acts no more). The pointers
// are the loop's own locals, so the compiler keeps them in registers across the stores to the
// forces.
template <int kNodes>
[[gnu::always_inline]] inline void scatter_spring_forces(const SpringBlock<kNodes>& block,
                                                         const Index* spring_nodes,
                                                         const std::uint8_t* broken, Index first,
                                                         Index count, Vec3* force, Index own_first,
                                                         Index own_end) {
  const Index* nodes = spring_nodes + static_cast<std::size_t>(kNodes) * first;
  for (Index k = 0; k < count; ++k, nodes += kNodes) {
    if (broken != nullptr && broken[first + k] != 0) {
      continue;
    }
    for (int j = 0; j < kNodes; ++j) {
      const Index node = nodes[j];
      if (node >= own_first && node < own_end) {
        double* f = force[node].data();
        f[0] += block.force[j].coordinate[0][k];
        f[1] += block.force[j].coordinate[1][k];
        f[2] += block.force[j].coordinate[2][k];
      }
    }
  }
}

// Adds the forces of every spring of one kind that the context's worker evaluates to its nodes,
// block by block in spring order, and keeps the plastic sets (and, while the energy is tracked,
// each spring's dissipation) of the springs whose first node it owns, when the context advances
// history. A spring that another worker evaluates too has its new plastic set put aside
// (State::plastic_set_updates) until every worker has read the old one: the worker that owns it
// writes it at the step's end, when the team has met (integrator.cpp).
template <int kNodes, class Kernel>
void add_spring_forces(ForceContext& context, const SpringArrays& springs, const Kernel& kernel) {
  const bool may_yield = springs.any_yield;
  const Vec3* x = context.state.x.data();
  Vec3* force = context.force.data();
  const auto [own_first, own_end] =
      context.worker.own_nodes(static_cast<Index>(context.state.x.size()));
  auto owns = [own_first, own_end](Index node) { return node >= own_first && node < own_end; };
  const bool whole = context.worker.split == nullptr;  // one thread evaluates every spring
  for_each_spring_chunk(
      context.worker, springs.share_runs, springs.count, kSpringBlockSize,
      [&](Index first, Index count) {
        const Index* spring_nodes = &springs.nodes[static_cast<std::size_t>(kNodes) * first];
        SpringBlock<kNodes> block;
        for (Index k = 0; k < count; ++k) {
          for (int j = 0; j < kNodes; ++j) {
            block.position[j].set(k, x[spring_nodes[kNodes * k + j]]);
          }
        }
        compute_spring_block(block, springs, first, count, kernel);
        scatter_spring_forces(block, springs.nodes.data(), springs.broken, first, count, force,
                              own_first, own_end);
        if (!may_yield || !context.update_history) {
          return;
        }
        // The history: on one thread in one plain loop; in a team, only for the springs whose
        // first node is this worker's, put aside where another worker reads them too.
        for (Index k = 0; k < count; ++k) {
          const Index s = first + k;
          const bool acts = springs.broken == nullptr || springs.broken[s] == 0;
          const double plastic_set = acts ? block.new_plastic_set[k] : springs.plastic_set[s];
          const Index* nodes = &springs.nodes[static_cast<std::size_t>(kNodes) * s];
          if (whole) {
            springs.plastic_set[s] = plastic_set;
          } else if (owns(nodes[0])) {
            bool all_own = true;
            for (int j = 1; j < kNodes; ++j) {
              all_own = all_own && owns(nodes[j]);
            }
            if (all_own) {
              springs.plastic_set[s] = plastic_set;
            } else {
              context.put_aside(&springs.plastic_set[s], plastic_set);
            }
          } else {
            continue;
          }
          if (springs.flow != nullptr) {
            (*springs.flow)[s] = acts ? block.dissipated[k] : 0.0;
          }
        }
      });
}

}  // namespace dinam
