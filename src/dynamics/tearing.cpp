#include "dynamics/tearing.hpp"

#include <cmath>

#include "dynamics/spring_kinds.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

double elastic_energy(const Model& model, const State& state) {
  double energy = 0.0;
  for (const SpringKind* kind : kSpringKinds) {
    energy += kind->energy(model, state, SpringEnergy::kStored);
  }
  return energy;
}

bool past_its_limit(const Model& model, const State& state, Index b) {
  if (model.bars_are_constraints()) {
    // Held as a constraint (bar_constraints.hpp): its tension is the last step's projection's,
    // −λ/h², and its strain what that tension stretches its material by, T / (E A).
    if (state.dt <= 0.0 || state.bar_lambda.empty()) {
      return false;
    }
    const double tension = -state.bar_lambda[b] / (state.dt * state.dt);
    return tension >= model.bar_breaking_force[b] || tension >= model.bar_breaking_strain[b] *
                                                                    model.bar_axial_stiffness[b] *
                                                                    model.bar_rest_length[b];
  }
  const Index n0 = model.bar_nodes[2 * b];
  const Index n1 = model.bar_nodes[2 * b + 1];
  const double length = (state.x[n1] - state.x[n0]).norm();
  const double rest = model.bar_rest_length[b];
  if (length - rest >= model.bar_breaking_strain[b] * rest) {
    return true;
  }
  // The axial spring's tension, as the kernel computes it (clamped at the yield force).
  const double tension = std::min(
      model.bar_axial_stiffness[b] * (length - rest - plastic_set_of(state.bar_plastic_set, b)),
      yield_limit(model.bar_yield_force, b));
  return tension >= model.bar_breaking_force[b];
}

void break_bar(const Model& model, Index b, State& state) {
  state.bar_broken[b] = 1;
  state.broken_bars.push_back(b);
  for (Index k = model.bar_spring_offsets[b]; k < model.bar_spring_offsets[b + 1]; ++k) {
    const Index id = model.bar_springs[k] / 3;
    (state.*spring_kind_torn_as(model.bar_springs[k] % 3).broken)[id] = 1;
  }
  for (Index k = model.bar_face_offsets[b]; k < model.bar_face_offsets[b + 1]; ++k) {
    state.face_broken[model.bar_faces[k]] = 1;
  }
}

}  // namespace

void prepare_tearing(const Model& model, State& state) {
  if (!model.can_tear()) {
    return;
  }
  for (const SpringKind* kind : kSpringKinds) {  // the axial springs' flags are the bars'
    (state.*kind->broken).assign(kind->count(model), 0);
  }
  state.face_broken.assign(model.face_count(), 0);
  state.broken_bars.reserve(static_cast<std::size_t>(model.bar_count()));  // steps allocate nothing
}

void break_overloaded_bars(const Model& model, State& state) {
  if (!model.can_tear()) {
    return;
  }
  double energy_before = 0.0;
  bool any = false;
  for (Index b = 0; b < model.bar_count(); ++b) {
    if (state.bar_broken[b] != 0 || !past_its_limit(model, state, b)) {
      continue;
    }
    if (!any && state.energy_workspace.enabled) {
      energy_before = elastic_energy(model, state);
    }
    any = true;
    break_bar(model, b, state);
  }
  if (any && state.energy_workspace.enabled) {
    state.energy.plastic_dissipation += energy_before - elastic_energy(model, state);
  }
}

}  // namespace dinam
