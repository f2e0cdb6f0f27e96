#include "dynamics/pin_motion.hpp"

#include <algorithm>
#include <cmath>

#include "model/model.hpp"

namespace dinam {

Vec3 driven_position(const Model& model, const PinMotion& motion, std::size_t k, double t) {
  if (motion.track.empty()) {
    return model.node_initial_x[motion.nodes[k]] + motion.profile(t) * motion.displacement;
  }
  const std::size_t driven = motion.nodes.size();
  const std::size_t last = motion.track.size() / driven - 1;
  const double at = std::max(t, 0.0) / motion.interval;
  if (at >= static_cast<double>(last)) {
    return motion.track[last * driven + k];
  }
  const auto before = static_cast<std::size_t>(std::floor(at));
  const double share = at - static_cast<double>(before);
  const Vec3& a = motion.track[before * driven + k];
  const Vec3& b = motion.track[(before + 1) * driven + k];
  return a + share * (b - a);
}

void place_driven_nodes(const Model& model, double t, State& state) {
  for (const PinMotion& motion : model.pin_motions) {
    for (std::size_t k = 0; k < motion.nodes.size(); ++k) {
      state.x[motion.nodes[k]] = driven_position(model, motion, k, t);
    }
  }
}

void set_driven_velocities(const Model& model, double t_next, double dt, const std::vector<Vec3>& x,
                           std::vector<Vec3>& v_half, const std::function<bool(Index)>& owns) {
  for (const PinMotion& motion : model.pin_motions) {
    for (std::size_t k = 0; k < motion.nodes.size(); ++k) {
      const Index node = motion.nodes[k];
      if (!owns || owns(node)) {
        v_half[node] = (driven_position(model, motion, k, t_next) - x[node]) / dt;
      }
    }
  }
}

}  // namespace dinam
