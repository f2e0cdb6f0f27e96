#include "dynamics/tie_springs.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "core/geometry.hpp"
#include "dynamics/bar_constraints.hpp"
#include "dynamics/broken.hpp"
#include "dynamics/parallel_loops.hpp"
#include "estimate/measured_costs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// A rest length this small is a node on its point: the spring is then ½ k |x − p|², smooth
// where the node crosses the point (|x − p| has no gradient there).
constexpr double kOnThePoint = 1e-9;  // m

template <class T>
using Point = Eigen::Matrix<T, 3, 1>;

// The forces of tie t on its node and its point's three nodes at positions `at` (coordinate by
// coordinate, so that T may be a Dual number: core/dual.hpp).
template <class T>
std::array<Point<T>, 4> tie_forces(const Model& model, Index t, const std::array<Point<T>, 4>& at) {
  const double* w = &model.ties.weights[3 * static_cast<std::size_t>(t)];
  const double length = model.ties.rest_length[t];
  const double k = model.ties.stiffness[t];
  Point<T> d;
  const Vec3& offset = model.ties.offset[t];
  for (int a = 0; a < 3; ++a) {
    d[a] = at[0][a] - (T(w[0]) * at[1][a] + T(w[1]) * at[2][a] + T(w[2]) * at[3][a]) - T(offset[a]);
  }
  T scale(-k);  // f_node = scale · d
  if (length > kOnThePoint) {
    using std::sqrt;
    const T r = sqrt(dot3(d, d));
    scale = r > T(0.0) ? T(-k) * (r - T(length)) / r : T(0.0);
  }
  std::array<Point<T>, 4> f;
  for (int a = 0; a < 3; ++a) {
    f[0][a] = scale * d[a];
    for (int j = 0; j < 3; ++j) {
      f[j + 1][a] = T(-w[j]) * f[0][a];
    }
  }
  return f;
}

std::array<Vec3, 4> positions_of(const Model& model, const std::vector<Vec3>& x, Index t) {
  const Index* nodes = &model.ties.nodes[4 * static_cast<std::size_t>(t)];
  return {x[nodes[0]], x[nodes[1]], x[nodes[2]], x[nodes[3]]};
}

// d = x − p − o of tie t at positions `x`: the node's way from where the tie holds it.
Vec3 separation(const Model& model, const std::vector<Vec3>& x, Index t) {
  const Index* nodes = &model.ties.nodes[4 * static_cast<std::size_t>(t)];
  const double* w = &model.ties.weights[3 * static_cast<std::size_t>(t)];
  return x[nodes[0]] - (w[0] * x[nodes[1]] + w[1] * x[nodes[2]] + w[2] * x[nodes[3]]) -
         model.ties.offset[t];
}

double stretch(const Model& model, const std::vector<Vec3>& x, Index t) {
  return separation(model, x, t).norm() - model.ties.rest_length[t];
}

double tie_energy(const Model& model, const State& state) {
  return sum_over_intact(state.tie_broken, model.ties.count(), [&](Index t) {
    const double s = stretch(model, state.x, t);
    return 0.5 * model.ties.stiffness[t] * s * s;
  });
}

// Every worker takes every tie and adds what falls on its own nodes: ties are few, and each node
// then sums them in tie order whatever the threads.
void add_tie_forces(ForceContext& context) {
  const Model& model = context.model;
  const State& state = context.state;
  for (Index t = 0; t < model.ties.count(); ++t) {
    if (is_broken(state.tie_broken, t)) {
      continue;
    }
    const Index* nodes = &model.ties.nodes[4 * static_cast<std::size_t>(t)];
    const std::array<Vec3, 4> f = tie_forces<double>(model, t, positions_of(model, state.x, t));
    for (int k = 0; k < 4; ++k) {
      if (context.worker.owns(nodes[k]) && !model.pinned(nodes[k])) {
        context.add(nodes[k], f[k]);
      }
    }
  }
}

void add_tie_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  add_spring_stiffness<4>(model.ties.count(), model.ties.nodes, state.tie_broken, state.x, sink,
                          [&](Index t, const std::array<Vec3, 4>& at) {
                            return local_stiffness<4>(at, [&](const auto& seeded) {
                              return tie_forces(model, t, seeded);
                            });
                          });
}

// One sweep of the ties' projection (XPBD, as the bars': dynamics/bar_constraints.hpp), in tie
// order, forward then back.
void project_ties(const Model& model, double h, int sweep, State& state) {
  const Ties& ties = model.ties;
  const Index count = ties.count();
  if (sweep == 0) {
    std::fill(state.tie_lambda.begin(), state.tie_lambda.end(), 0.0);
  }
  std::vector<Vec3>& x = state.x_next;
  for (Index k = 0; k < count; ++k) {
    const Index t = sweep % 2 == 0 ? k : count - 1 - k;
    if (is_broken(state.tie_broken, t)) {
      continue;
    }
    const Index* nodes = &ties.nodes[4 * static_cast<std::size_t>(t)];
    const double* w = &ties.weights[3 * static_cast<std::size_t>(t)];
    const Vec3 d = separation(model, x, t);
    const double r = d.norm();
    if (!(r > 0.0)) {
      continue;
    }
    const Vec3 n = d / r;
    const double compliance = ties.rigid[t] != 0 ? 0.0 : 1.0 / (ties.stiffness[t] * h * h);
    double weight = model.node_inv_mass[nodes[0]];
    for (int j = 0; j < 3; ++j) {
      weight += w[j] * w[j] * model.node_inv_mass[nodes[j + 1]];
    }
    if (weight + compliance <= 0.0) {
      continue;  // every node of it pinned
    }
    double& lambda = state.tie_lambda[t];
    const double delta = -((r - ties.rest_length[t]) + compliance * lambda) / (weight + compliance);
    lambda += delta;
    x[nodes[0]] += (model.node_inv_mass[nodes[0]] * delta) * n;
    for (int j = 0; j < 3; ++j) {
      x[nodes[j + 1]] -= (w[j] * model.node_inv_mass[nodes[j + 1]] * delta) * n;
    }
  }
}

// After the sweeps: each tie's tension, −λ/h², for its break check.
void note_tie_tensions(const Model& model, double h, State& state) {
  for (Index t = 0; t < model.ties.count(); ++t) {
    state.tie_tension[t] = -state.tie_lambda[t] / (h * h);
  }
}

}  // namespace

double tie_tension(const Model& model, const State& state, Index tie) {
  if (!state.tie_tension.empty() && !std::isnan(state.tie_tension[tie])) {
    return state.tie_tension[tie];
  }
  return model.ties.stiffness[tie] * stretch(model, state.x, tie);
}

void break_overloaded_ties(const Model& model, State& state) {
  if (!model.ties.can_break) {
    return;
  }
  for (Index t = 0; t < model.ties.count(); ++t) {
    if (is_broken(state.tie_broken, t) ||
        !(std::abs(tie_tension(model, state, t)) > model.ties.break_force[t])) {
      continue;
    }
    if (state.energy_workspace.enabled) {
      const double s = stretch(model, state.x, t);
      state.energy.plastic_dissipation += 0.5 * model.ties.stiffness[t] * s * s;
    }
    state.tie_broken[t] = 1;
  }
}

const ForceKind kTies{
    .label = "ties",
    .spring = nullptr,
    .role = ForceRole::kPotential,
    .implicit = ImplicitTreatment::kInPotential,
    .damper = {},
    .switched = &ForceSwitches::ties,
    .present = [](const Model& model) { return model.ties.count() > 0; },
    .prepare_forces = nullptr,
    .add_forces = [](ForceContext& total, const StepOptions&) { add_tie_forces(total); },
    .add_forces_after_team = nullptr,
    .add_potential = [](const Model& model, const State& state, const PotentialQuery&,
                        Potential& potential) { potential.add(tie_energy(model, state)); },
    .add_stiffness = add_tie_stiffness,
    // Booked with the axial springs: a tie is one more spring along a line.
    .report_energy = [](const Model& model, const State& state,
                        EnergyReport& report) { report.axial += tie_energy(model, state); },
    .ledger = {},
    .prepare_state =
        [](const Model& model, State& state) {
          const auto count = static_cast<std::size_t>(model.ties.count());
          state.tie_broken.assign(model.ties.can_break ? count : 0, 0);
          state.tie_lambda.assign(model.bars_are_constraints() ? count : 0, 0.0);
          // Not known before the first projection: the spring's own until then (the settle's).
          state.tie_tension.assign(model.bars_are_constraints() ? count : 0,
                                   std::numeric_limits<double>::quiet_NaN());
        },
    .state_bytes = [](const Model& model, bool) -> std::uint64_t {
      const auto count = static_cast<std::uint64_t>(model.ties.count());
      return (model.ties.can_break ? count : 0) +
             (model.bars_are_constraints() ? 2 * count * sizeof(double) : 0);
    },
    .add_cost =
        [](const Model& model, StepCostSink& sink) {
          sink.add("ties", static_cast<double>(model.ties.count()), measured::kNsPerTie);
        },
    .constraint = {.held = true,
                   .project = project_ties,
                   .finish = note_tie_tensions,
                   .add_cost =
                       [](const Model& model, StepCostSink& sink) {
                         sink.add("ties' projection",
                                  static_cast<double>(kConstraintSweeps * model.ties.count()),
                                  measured::kNsPerBarProjection);
                       }},
};

}  // namespace dinam
