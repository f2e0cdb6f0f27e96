#include "dynamics/bending_spring.hpp"

#include "dynamics/parallel_loops.hpp"
#include "dynamics/spring_block.hpp"
#include "model/model.hpp"

namespace dinam {

#ifdef DINAM_FLOAT_BENDING
namespace {

// The single-precision trial (docs/performance.md, "Float32"): for elastic springs, each block
// gathers its bars relative to the centre node in float, and the kernel runs in float only, eight
// springs a vector; the forces are added to the nodes in double.
bool add_elastic_bending_forces_in_float(ForceContext& context) {
  const Model& model = context.model;
  if (model.bend_colours.any_yield || !context.state.bend_broken.empty()) {
    return false;
  }
  const Vec3* x = context.state.x.data();
  Vec3* force = context.force.data();
  for_each_spring_block(model.bend_colours, [&](Index first, Index count) {
    const Index* nodes = &model.bend_nodes[3 * static_cast<std::size_t>(first)];
    float e[2][3][kSpringBlockSize];
    float rest[kSpringBlockSize];
    float stiffness[kSpringBlockSize];
    float f[3][3][kSpringBlockSize];
    for (Index k = 0; k < count; ++k) {
      const Vec3& xc = x[nodes[3 * k + 1]];
      for (int side = 0; side < 2; ++side) {
        const Vec3 d = x[nodes[3 * k + 2 * side]] - xc;
        for (int a = 0; a < 3; ++a) {
          e[side][a][k] = static_cast<float>(d[a]);
        }
      }
      rest[k] = static_cast<float>(model.bend_rest_angle[first + k]);
      stiffness[k] = static_cast<float>(model.bend_stiffness[first + k]);
    }
    for (Index k = 0; k < count; ++k) {
      const BendingSpringResultT<float> r =
          bending_spring<float>(Vec3f(e[0][0][k], e[0][1][k], e[0][2][k]), Vec3f::Zero(),
                                Vec3f(e[1][0][k], e[1][1][k], e[1][2][k]), rest[k], stiffness[k]);
      for (int a = 0; a < 3; ++a) {
        f[0][a][k] = r.force_a[a];
        f[1][a][k] = r.force_c[a];
        f[2][a][k] = r.force_b[a];
      }
    }
    for (Index k = 0; k < count; ++k) {
      for (int j = 0; j < 3; ++j) {
        force[nodes[3 * k + j]] += Vec3(f[j][0][k], f[j][1][k], f[j][2][k]);
      }
    }
  });
  return true;
}

}  // namespace
#endif

void add_bending_spring_forces(ForceContext& context) {
#ifdef DINAM_FLOAT_BENDING
  if (add_elastic_bending_forces_in_float(context)) {
    return;
  }
#endif
  const Model& model = context.model;
  const SpringArrays springs{model.bend_colours,
                             model.bend_nodes,
                             model.bend_rest_angle,
                             model.bend_stiffness,
                             model.bend_yield_moment,
                             context.state.bend_plastic_set,
                             broken_flags(context.state.bend_broken)};
  add_spring_forces<3>(
      context, springs,
      [](SpringBlock<3> & block, Index k, double rest, double stiffness, double plastic_set,
         double yield) __attribute__((always_inline)) {
        const BendingSpringResult r =
            bending_spring(block.node_position(0, k), block.node_position(1, k),
                           block.node_position(2, k), rest, stiffness, plastic_set, yield);
        block.set_force(0, k, r.force_a);
        block.set_force(1, k, r.force_c);
        block.set_force(2, k, r.force_b);
        block.new_plastic_set[k] = r.plastic_set;
        block.dissipated[k] = r.dissipated;
      });
}

double bending_spring_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index s = 0; s < model.bend_count(); ++s) {
    if (!state.bend_broken.empty() && state.bend_broken[s] != 0) {
      continue;
    }
    const Index* nodes = &model.bend_nodes[3 * s];
    energy += bending_spring(state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]],
                             model.bend_rest_angle[s], model.bend_stiffness[s],
                             plastic_set_of(state.bend_plastic_set, s),
                             yield_limit(model.bend_yield_moment, s))
                  .energy;
  }
  return energy;
}

}  // namespace dinam
