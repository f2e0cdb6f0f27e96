#include "dynamics/bending_spring.hpp"

#include "core/geometry.hpp"
#include "dynamics/elastoplastic.hpp"
#include "dynamics/parallel_loops.hpp"
#include "model/model.hpp"

namespace dinam {

BendingSpringResult bending_spring(const Vec3& xa, const Vec3& xc, const Vec3& xb,
                                   double rest_angle, double stiffness, double plastic_set,
                                   double yield) {
  const Vec3 e1 = xa - xc;
  const Vec3 e2 = xb - xc;
  const double l1 = e1.norm();
  const double l2 = e2.norm();
  BendingSpringResult result{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 0.0, plastic_set, 0.0};
  if (l1 <= 0.0 || l2 <= 0.0) {
    return result;
  }
  const Vec3 u = e1 / l1;
  const Vec3 w = e2 / l2;
  const double c = u.dot(w);
  const double s = u.cross(w).norm();
  const double angle = fast_atan2(s, c);
  const ElastoplasticResult r = elastoplastic(angle - rest_angle, plastic_set, stiffness, yield);
  result.energy = r.energy;
  result.plastic_set = r.plastic_set;
  result.dissipated = r.dissipated;
  // Below this sine the in-plane directions are lost in rounding (|w − c u| ~ s).
  constexpr double kMinSine = 1e-9;
  if (s < kMinSine) {
    return result;
  }
  const Vec3 grad_a = -(w - c * u) / (l1 * s);
  const Vec3 grad_b = -(u - c * w) / (l2 * s);
  result.force_a = -r.force * grad_a;
  result.force_b = -r.force * grad_b;
  result.force_c = -(result.force_a + result.force_b);
  return result;
}

void add_bending_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  State& state = context.state;
  for_each_spring_by_colour(model.bend_colours, [&](Index s) {
    const Index a = model.bend_nodes[3 * s];
    const Index c = model.bend_nodes[3 * s + 1];
    const Index b = model.bend_nodes[3 * s + 2];
    const BendingSpringResult r = bending_spring(
        state.x[a], state.x[c], state.x[b], model.bend_rest_angle[s], model.bend_stiffness[s],
        state.bend_plastic_set[s], model.bend_yield_moment[s]);
    context.force[a] += r.force_a;
    context.force[c] += r.force_c;
    context.force[b] += r.force_b;
    context.record_plastic_flow(s, state.bend_plastic_set[s], r.plastic_set, r.dissipated);
  });
  context.book_plastic_flow(model.bend_colours);
}

double bending_spring_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index s = 0; s < model.bend_count(); ++s) {
    const Index* nodes = &model.bend_nodes[3 * s];
    energy += bending_spring(state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]],
                             model.bend_rest_angle[s], model.bend_stiffness[s],
                             state.bend_plastic_set[s], model.bend_yield_moment[s])
                  .energy;
  }
  return energy;
}

}  // namespace dinam
