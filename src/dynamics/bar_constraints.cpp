#include "dynamics/bar_constraints.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/spring_kind.hpp"
#include "dynamics/state.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Draws bar b towards its rest length (the header's Δλ), its tension held within its yield force.
void project_bar(const Model& model, double h, Index b, State& state) {
  const double k = model.bar_axial_stiffness[b];
  if (k <= 0.0 || (!state.bar_broken.empty() && state.bar_broken[b] != 0)) {
    return;
  }
  const Index i = model.bar_nodes[2 * b];
  const Index j = model.bar_nodes[2 * b + 1];
  const double wi = model.node_inv_mass[i];
  const double wj = model.node_inv_mass[j];
  std::vector<Vec3>& x = state.x_next;
  const Vec3 d = x[j] - x[i];
  const double length = d.norm();
  if (wi + wj == 0.0 || length == 0.0) {
    return;  // held at both ends, or no direction to draw it along
  }
  const Vec3 n = d / length;
  const double compliance = 1.0 / (k * h * h);  // α̃
  const double gamma = model.bar_damping.empty() ? 0.0 : model.bar_damping[b] / (k * h);
  const double stretch =
      length - model.bar_rest_length[b] - plastic_set_of(state.bar_plastic_set, b);  // C
  const double moved = n.dot((x[j] - state.x[j]) - (x[i] - state.x[i]));  // ∇C·(x − x_n)
  double& lambda = state.bar_lambda[b];
  const double unheld = lambda - (stretch + compliance * lambda + gamma * moved) /
                                     ((1.0 + gamma) * (wi + wj) + compliance);
  // |λ|/h² is the bar's force: held at its yield force, where it flows (the step's end moves its
  // plastic set on).
  const double most = yield_limit(model.bar_yield_force, b) * h * h;
  const double held = std::clamp(unheld, -most, most);
  const double change = held - lambda;
  lambda = held;
  x[i] -= (wi * change) * n;
  x[j] += (wj * change) * n;
}

// After the last sweep: a bar held at its yield force keeps as its new plastic set what it is
// stretched by beyond its elastic share, C + α̃ λ (the elastic stretch being −α̃ λ), and while
// the energy is tracked the flow's work, the yield force times the set's change.
void flow_yielding_bars(const Model& model, double h, State& state) {
  const std::vector<Vec3>& x = state.x_next;
  for (Index b = 0; b < model.bar_count(); ++b) {
    const double k = model.bar_axial_stiffness[b];
    const double yield = model.bar_yield_force[b];
    const double lambda = state.bar_lambda[b];
    if (k <= 0.0 || std::abs(lambda) < yield * h * h ||
        (!state.bar_broken.empty() && state.bar_broken[b] != 0)) {
      continue;
    }
    const double length = (x[model.bar_nodes[2 * b + 1]] - x[model.bar_nodes[2 * b]]).norm();
    double& set = state.bar_plastic_set[b];
    const double stretch = length - model.bar_rest_length[b] - set;
    const double flow = stretch + lambda / (k * h * h);
    set += flow;
    if (state.energy_workspace.enabled) {
      state.energy_workspace.bar_flow[b] = yield * std::abs(flow);
    }
  }
}

}  // namespace

void project_bars(const Model& model, double h, int sweep, State& state) {
  const Index bars = model.bar_count();
  if (sweep == 0) {
    std::fill(state.bar_lambda.begin(), state.bar_lambda.end(), 0.0);
    std::fill(state.energy_workspace.bar_flow.begin(), state.energy_workspace.bar_flow.end(), 0.0);
  }
  if (sweep % 2 == 0) {
    for (Index b = 0; b < bars; ++b) {
      project_bar(model, h, b, state);
    }
  } else {
    for (Index b = bars - 1; b >= 0; --b) {
      project_bar(model, h, b, state);
    }
  }
}

void flow_bars(const Model& model, double h, State& state) {
  if (model.bars_yield) {
    flow_yielding_bars(model, h, state);
  }
}

}  // namespace dinam
