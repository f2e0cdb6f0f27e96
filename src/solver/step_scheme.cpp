#include "solver/step_scheme.hpp"

#include <algorithm>
#include <utility>

#include "dynamics/pin_motion.hpp"
#include "model/model.hpp"

namespace dinam {

void StepScheme::set_base(const Model& model, const State& state, double step) {
  h = step;
  x_start = state.x;
  v_start = state.velocity;  // v_n: the implicit integrator keeps full-step velocities there
  t_next = state.time + h;
  const bool two_step = model.implicit_scheme == ImplicitScheme::kBdf2 && before_h == h;
  hs = two_step ? 2.0 * h / 3.0 : h;
  x_base = x_start;
  v_base = v_start;
  if (two_step) {
    for (std::size_t i = 0; i < x_start.size(); ++i) {
      x_base[i] = (4.0 * x_start[i] - x_before[i]) / 3.0;
      v_base[i] = (4.0 * v_start[i] - v_before[i]) / 3.0;
    }
  }
}

void StepScheme::predict(const Model& model, const std::vector<Vec3>& loads,
                         std::vector<Vec3>& predicted, State& state) const {
  const std::size_t n = state.x.size();
  predicted.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    predicted[i] = x_base[i] + hs * v_base[i] + (hs * hs * model.node_inv_mass[i]) * loads[i];
  }
  place_driven_nodes(model, t_next, state);
}

void StepScheme::restore(State& state) const {
  state.x = x_start;
  state.velocity = v_start;
  state.time = t_next - h;
}

bool StepScheme::accept(const Model& model, State& state, bool check_error, bool contact_changed,
                        double limit) {
  const std::size_t n = state.x.size();
  double error = 0.0;
  accel.assign(n, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 v = (state.x[i] - x_base[i]) / hs;
    accel[i] = (v - v_start[i]) / h;
    if (have_accel && !model.pinned(static_cast<Index>(i))) {
      error = std::max(error, 0.5 * h * h * (accel[i] - accel_before[i]).norm());
    }
    state.velocity[i] = v;
  }
  return !(check_error && !contact_changed && error > limit);
}

void StepScheme::keep_history(const Model& model, State& state, bool contact_changed,
                              bool rebounded) {
  std::swap(accel_before, accel);
  have_accel = !contact_changed;
  if (model.implicit_scheme == ImplicitScheme::kBdf2) {
    x_before = x_start;
    v_before = v_start;
    before_h = rebounded ? 0.0 : h;
  }
  state.time = t_next;
  state.step += 1;
}

}  // namespace dinam
