#include "dynamics/settle.hpp"

#include <cmath>

#include "dynamics/integrator.hpp"
#include "model/model.hpp"

namespace dinam {

void relax_by_kinetic_damping(const Model& model, double dt, const ForceSwitches& switches,
                              std::int64_t steps, State& state) {
  // The motion runs on, and whenever the kinetic energy has passed a peak every velocity is
  // zeroed. Each reset removes energy near a point of lowest potential, so the structure walks
  // down to a static equilibrium; unlike viscous damping it also settles the soft, slow modes (a
  // hanging cloth's folds) in a few of their periods.
  double previous_kinetic = 0.0;
  for (std::int64_t s = 0; s < steps; ++s) {
    step(model, dt, switches, state);
    double kinetic = 0.0;
    for (Index i = 0; i < model.node_count(); ++i) {
      kinetic += model.node_mass[i] * state.v_half[i].squaredNorm();
    }
    if (kinetic < previous_kinetic) {
      for (Index i = 0; i < model.node_count(); ++i) {
        state.v_half[i].setZero();
      }
      kinetic = 0.0;
    }
    previous_kinetic = kinetic;
  }
}

void settle_under_gravity(const Model& model, double dt, const ForceSwitches& switches,
                          State& state) {
  if (model.settle.duration <= 0.0) {
    return;
  }
  // The same structure at rest with nothing but gravity and the ground acting. A copy is made once
  // per run, which is cheap beside the steps that follow.
  Model quiet = model;
  quiet.fields.clear();
  quiet.wind.faces.clear();
  quiet.wind.bars.clear();
  quiet.pin_motions.clear();  // supports hold still where they start
  for (Vec3& v : quiet.node_initial_v) {
    v.setZero();
  }
  quiet.settle = {};
  quiet.node_initial_x = state.x;

  State settling = initial_state(quiet, dt, switches, false);
  relax_by_kinetic_damping(quiet, dt, switches,
                           static_cast<std::int64_t>(std::llround(model.settle.duration / dt)),
                           settling);
  state.x = std::move(settling.x);
  state.bar_plastic_set = std::move(settling.bar_plastic_set);
  state.bend_plastic_set = std::move(settling.bend_plastic_set);
  state.torsion_plastic_set = std::move(settling.torsion_plastic_set);
  state.clamp_plastic_set = std::move(settling.clamp_plastic_set);
  state.contact_anchor = std::move(settling.contact_anchor);
  state.contact_touching = std::move(settling.contact_touching);
  state.contact_sliding = std::move(settling.contact_sliding);
}

}  // namespace dinam
