#include "core/geometry.hpp"
#include "model/spring_builders.hpp"

namespace dinam {
namespace {

// The sine of the angle between two directions.
double sine_between(const Vec3& u, const Vec3& v) {
  return u.cross(v).norm() / (u.norm() * v.norm());
}

}  // namespace

void add_torsion_springs(const BarMaterials& materials, const ModelObject& object,
                         const NodeAdjacency& adjacency, Model& model) {
  for (Index bar = object.first_bar; bar < object.first_bar + object.bar_count; ++bar) {
    const MaterialDesc& material = *materials[bar - object.first_bar];
    const double gj = material.shear_modulus * material.polar_moment;
    const Index i = model.bar_nodes[2 * bar];
    const Index j = model.bar_nodes[2 * bar + 1];
    const Vec3 axis = model.node_initial_x[j] - model.node_initial_x[i];
    // The best pair of references (a at i, b at j, a ≠ b): the one whose worse end is most
    // nearly perpendicular to the bar.
    Index best_a = -1;
    Index best_b = -1;
    double best_sine = kMinReferenceSine;
    for (const auto& [a, bar_a] : adjacency[i - object.first_node]) {
      if (bar_a == bar) {
        continue;
      }
      const double sine_a = sine_between(model.node_initial_x[a] - model.node_initial_x[i], axis);
      for (const auto& [b, bar_b] : adjacency[j - object.first_node]) {
        if (bar_b == bar || b == a) {
          continue;
        }
        const double sine_b = sine_between(model.node_initial_x[b] - model.node_initial_x[j], axis);
        const double worse = std::min(sine_a, sine_b);
        if (worse >= best_sine) {
          best_sine = worse;
          best_a = a;
          best_b = b;
        }
      }
    }
    if (best_a < 0) {
      ++model.bars_without_torsion;
      continue;
    }
    model.torsion_nodes.insert(model.torsion_nodes.end(), {best_a, i, j, best_b});
    model.torsion_rest_angle.push_back(
        dihedral_angle(model.node_initial_x[best_a], model.node_initial_x[i],
                       model.node_initial_x[j], model.node_initial_x[best_b]));
    // Per unit of the weight q_a q_b (torsion_spring.hpp), which is q_a0 q_b0 at rest.
    const double sine_a =
        sine_between(model.node_initial_x[best_a] - model.node_initial_x[i], axis);
    const double sine_b =
        sine_between(model.node_initial_x[best_b] - model.node_initial_x[j], axis);
    const double rest_weight = sine_a * sine_a * sine_b * sine_b;
    model.torsion_stiffness.push_back(gj / model.bar_rest_length[bar] / rest_weight);
    model.torsion_yield_moment.push_back(material.yield_torsion_moment);
  }
}

}  // namespace dinam
