#include "dynamics/pin_motion.hpp"

#include "model/model.hpp"

namespace dinam {

void place_driven_nodes(const Model& model, double t, State& state) {
  for (const PinMotion& motion : model.pin_motions) {
    const Vec3 offset = motion.profile(t) * motion.displacement;
    for (const Index node : motion.nodes) {
      state.x[node] = model.node_initial_x[node] + offset;
    }
  }
}

void set_driven_velocities(const Model& model, double t_next, double dt, const std::vector<Vec3>& x,
                           std::vector<Vec3>& v_half, const std::function<bool(Index)>& owns) {
  for (const PinMotion& motion : model.pin_motions) {
    const Vec3 offset = motion.profile(t_next) * motion.displacement;
    for (const Index node : motion.nodes) {
      if (!owns || owns(node)) {
        v_half[node] = (model.node_initial_x[node] + offset - x[node]) / dt;
      }
    }
  }
}

}  // namespace dinam
