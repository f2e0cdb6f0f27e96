#include "dynamics/bar_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dynamics/spring_kind.hpp"
#include "dynamics/state.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Each bar's record for steps of h (BarProjection), in the model's sweep order.
void pack_bars(const Model& model, double h, State& state) {
  for (Index place = 0; place < model.bar_count(); ++place) {
    const Index b = model.bar_sweep_order[place];
    BarProjection& bar = state.bar_projection[place];
    bar.bar = b;
    bar.i = model.bar_nodes[2 * b];
    bar.j = model.bar_nodes[2 * b + 1];
    bar.wi = model.node_inv_mass[bar.i];
    bar.wj = model.node_inv_mass[bar.j];
    bar.rest = model.bar_rest_length[b];
    const double k = model.bar_axial_stiffness[b];
    bar.compliance = 0.0;
    bar.gamma = 0.0;
    bar.denominator = 0.0;
    if (k <= 0.0 || bar.wi + bar.wj == 0.0) {
      continue;  // no constraint: a sheet's shared side, or held at both ends
    }
    bar.compliance = 1.0 / (k * h * h);
    bar.gamma = model.bar_damping.empty() ? 0.0 : model.bar_damping[b] / (k * h);
    bar.denominator = 1.0 / ((1.0 + bar.gamma) * (bar.wi + bar.wj) + bar.compliance);
  }
  state.bar_projection_step = h;
}

// Draws a bar towards its rest length (the header's Δλ), its tension held within its yield force.
void project_bar(const Model& model, double h, const BarProjection& bar, State& state) {
  const Index b = bar.bar;
  if (bar.compliance == 0.0 || (!state.bar_broken.empty() && state.bar_broken[b] != 0)) {
    return;
  }
  std::vector<Vec3>& x = state.x_next;
  const Vec3 d = x[bar.j] - x[bar.i];
  const double length = d.norm();
  if (length == 0.0) {
    return;  // no direction to draw it along
  }
  const Vec3 n = d * (1.0 / length);
  const double stretch = length - bar.rest - plastic_set_of(state.bar_plastic_set, b);  // C
  double& lambda = state.bar_lambda[b];
  double residual = stretch + bar.compliance * lambda;
  if (bar.gamma != 0.0) {  // γ ∇C·(x − x_n)
    residual += bar.gamma * n.dot((x[bar.j] - state.x[bar.j]) - (x[bar.i] - state.x[bar.i]));
  }
  // |λ|/h² is the bar's force: held at its yield force, where it flows (the step's end moves its
  // plastic set on).
  const double most = yield_limit(model.bar_yield_force, b) * h * h;
  const double held = std::clamp(lambda - residual * bar.denominator, -most, most);
  const double change = held - lambda;
  lambda = held;
  x[bar.i] -= (bar.wi * change) * n;
  x[bar.j] += (bar.wj * change) * n;
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

double bar_constraint_step_cap(const Model& model) {
  double load = model.gravity.norm();  // m/s², the largest acceleration the loads may give a node
  for (const FieldForce& field : model.fields) {
    double lightest = std::numeric_limits<double>::infinity();
    for (const Index i : field.nodes) {
      lightest = std::min(lightest, model.node_mass[i]);
    }
    load += field.per_unit_mass ? field.value.norm() : field.value.norm() / lightest;
  }
  std::vector<double> lengths = model.bar_rest_length;
  if (lengths.empty() || !(load > 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return std::sqrt(kLoadStretchShare * lengths[lengths.size() / 2] / load);
}

void project_bars(const Model& model, double h, int sweep, State& state) {
  const Index bars = model.bar_count();
  if (sweep == 0) {
    std::fill(state.bar_lambda.begin(), state.bar_lambda.end(), 0.0);
    std::fill(state.energy_workspace.bar_flow.begin(), state.energy_workspace.bar_flow.end(), 0.0);
  }
  if (state.bar_projection_step != h) {
    pack_bars(model, h, state);
  }
  if (sweep % 2 == 0) {
    for (Index k = 0; k < bars; ++k) {
      project_bar(model, h, state.bar_projection[k], state);
    }
  } else {
    for (Index k = bars - 1; k >= 0; --k) {
      project_bar(model, h, state.bar_projection[k], state);
    }
  }
}

void flow_bars(const Model& model, double h, State& state) {
  if (model.bars_yield) {
    flow_yielding_bars(model, h, state);
  }
}

}  // namespace dinam
