#include "dynamics/contact/ground_restitution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/model.hpp"

namespace dinam {

double spring_dashpot_restitution(double zeta) {
  if (zeta >= 1.0) {
    return 0.0;
  }
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double phase = std::numbers::pi - std::atan2(2.0 * zeta * root, 1.0 - 2.0 * zeta * zeta);
  return std::exp(-zeta * phase / root) * std::abs(std::cos(phase) - zeta / root * std::sin(phase));
}

bool rebound_landing_nodes(const Model& model, const std::vector<Vec3>& x_start,
                           const std::vector<Vec3>& v_start, State& state) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return false;
  }
  const Vec3& normal = ground.normal;
  const double pull = std::max(-model.gravity.dot(normal), 0.0);  // m/s², towards the plane
  bool any = false;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.pinned(i)) {
      continue;
    }
    const double height = ground.clearance(i, x_start[i]);
    if (height < 0.0 || ground.clearance(i, state.x[i]) >= 0.0) {
      continue;
    }
    const double approach = v_start[i].dot(normal);  // either way: a fall's speed at the plane
    const double k = ground.node_stiffness[i];
    const double m = model.node_mass[i];
    const double zeta = ground.node_damping[i] / (2.0 * std::sqrt(k * m));
    const double struck = std::sqrt(approach * approach + 2.0 * pull * height);
    const double leaving = spring_dashpot_restitution(zeta) * struck;
    Vec3& v = state.velocity[i];
    const double along = v.dot(normal);
    if (along < leaving) {
      v += (leaving - along) * normal;
      any = true;
    }
  }
  return any;
}

}  // namespace dinam
