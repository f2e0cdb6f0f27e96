#include "dynamics/torsion_spring.hpp"

#include "core/geometry.hpp"
#include "dynamics/elastoplastic.hpp"
#include "dynamics/parallel_loops.hpp"
#include "model/model.hpp"

namespace dinam {

TorsionSpringResult torsion_spring(const Vec3& xa, const Vec3& xi, const Vec3& xj, const Vec3& xb,
                                   double rest_angle, double stiffness, double plastic_set,
                                   double yield) {
  const Vec3 b1 = xi - xa;
  const Vec3 b2 = xj - xi;
  const Vec3 b3 = xb - xj;
  const Vec3 n1 = b1.cross(b2);
  const Vec3 n2 = b2.cross(b3);
  const double b2_norm = b2.norm();
  const double angle = fast_atan2(b2_norm * b1.dot(n2), n1.dot(n2));
  // The plastic set accumulates unwrapped; only the elastic part is taken the short way round.
  const double deformation = plastic_set + wrap_angle(angle - rest_angle - plastic_set);
  const ElastoplasticResult r = elastoplastic(deformation, plastic_set, stiffness, yield);
  TorsionSpringResult result{Vec3::Zero(), Vec3::Zero(),  Vec3::Zero(), Vec3::Zero(),
                             r.energy,     r.plastic_set, r.dissipated};
  const double n1_squared = n1.squaredNorm();
  const double n2_squared = n2.squaredNorm();
  // Relative to the bar's own scale, below this a reference plane is numerically undefined.
  const double tiny = 1e-18 * b2_norm * b2_norm * (b1.squaredNorm() + b3.squaredNorm());
  if (b2_norm <= 0.0 || n1_squared <= tiny || n2_squared <= tiny) {
    return result;
  }
  const Vec3 grad_a = -(b2_norm / n1_squared) * n1;
  const Vec3 grad_b = (b2_norm / n2_squared) * n2;
  const double s1 = b1.dot(b2) / (b2_norm * b2_norm);
  const double s3 = b3.dot(b2) / (b2_norm * b2_norm);
  const Vec3 grad_i = -(1.0 + s1) * grad_a + s3 * grad_b;
  const Vec3 grad_j = -(1.0 + s3) * grad_b + s1 * grad_a;
  result.force_a = -r.force * grad_a;
  result.force_i = -r.force * grad_i;
  result.force_j = -r.force * grad_j;
  result.force_b = -r.force * grad_b;
  return result;
}

void add_torsion_spring_forces(ForceContext& context) {
  const Model& model = context.model;
  State& state = context.state;
  for_each_spring_by_colour(model.torsion_colours, [&](Index s) {
    const Index* nodes = &model.torsion_nodes[4 * s];
    const TorsionSpringResult r =
        torsion_spring(state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]], state.x[nodes[3]],
                       model.torsion_rest_angle[s], model.torsion_stiffness[s],
                       state.torsion_plastic_set[s], model.torsion_yield_moment[s]);
    context.force[nodes[0]] += r.force_a;
    context.force[nodes[1]] += r.force_i;
    context.force[nodes[2]] += r.force_j;
    context.force[nodes[3]] += r.force_b;
    context.record_plastic_flow(s, state.torsion_plastic_set[s], r.plastic_set, r.dissipated);
  });
  context.book_plastic_flow(model.torsion_colours);
}

double torsion_spring_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (Index s = 0; s < model.torsion_count(); ++s) {
    const Index* nodes = &model.torsion_nodes[4 * s];
    energy +=
        torsion_spring(state.x[nodes[0]], state.x[nodes[1]], state.x[nodes[2]], state.x[nodes[3]],
                       model.torsion_rest_angle[s], model.torsion_stiffness[s],
                       state.torsion_plastic_set[s], model.torsion_yield_moment[s])
            .energy;
  }
  return energy;
}

}  // namespace dinam
