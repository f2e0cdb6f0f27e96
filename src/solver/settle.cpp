#include "solver/settle.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "dynamics/contact/contact_pairs.hpp"
#include "dynamics/contact/ground_contact.hpp"
#include "dynamics/relaxation.hpp"
#include "dynamics/spring_kinds.hpp"
#include "dynamics/state_arrays.hpp"
#include "dynamics/tearing.hpp"
#include "model/model.hpp"
#include "model/tie_builder.hpp"
#include "solver/equilibrium.hpp"

namespace dinam {
namespace {

// Newton iterations before the settle gives up on the method and relaxes instead. The flag takes
// a few dozen from its mesh; a structure that needs hundreds is close to a mechanism.
constexpr int kMostNewtonIterations = 300;
// Iterations Newton's method has to finish from a restart of relaxation: near an equilibrium it
// converges quadratically, in a handful; more means it is not near enough yet.
constexpr int kFinishingIterations = 12;

constexpr const char* kSlopeReason =
    "the ground slopes under gravity, and friction holds what rests on it";

// Why the equilibrium cannot be found statically for this model at all (empty: it can).
std::string why_not_static(const Model& model) {
  // Under gravity, an object with no pinned node, no tie to another and no ground below it has no
  // equilibrium.
  if (model.gravity.norm() > 0.0 && !model.ground.enabled) {
    const std::vector<std::uint8_t> tied = tied_nodes(model);
    for (const ModelObject& object : model.objects) {
      bool held = false;
      for (Index i = object.first_node; i < object.first_node + object.node_count && !held; ++i) {
        held = model.pinned(i) || tied[static_cast<std::size_t>(i)] != 0;
      }
      if (!held) {
        return fmt::format(
            "object '{}' is held by nothing (no pinned node, no ground), so it "
            "has no equilibrium",
            object.name);
      }
    }
  }
  return {};
}

// Whether the ground's plane is not square to gravity.
bool ground_slopes(const Model& model) {
  const double g = model.gravity.norm();
  return g > 0.0 && model.ground.normal.cross(model.gravity / g).norm() > 1e-9;
}

// Whether a free node at `at` rests on a ground that slopes under gravity, where friction holds it
// (Newton's potential has none: without it the structure slides off, and has no equilibrium).
bool on_sloping_ground(const Model& model, const State& at) {
  if (!model.ground.enabled || !ground_slopes(model)) {
    return false;
  }
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i) && model.ground.clearance(i, at.x[i]) < 0.0) {
      return true;
    }
  }
  return false;
}

// Why the equilibrium Newton's method found at `settled` is not the one the structure would reach
// (empty: it is): friction, yielding or tearing on the way.
std::string why_path_matters(const Model& model, const ForceSwitches& quiet, const State& settled) {
  if (on_sloping_ground(model, settled)) {
    return kSlopeReason;
  }
  // Newton's potential holds no contact between objects: its equilibrium stands where nothing
  // touches (a flag hanging clear of its pole), not where a body rests on another, whose place
  // depends on how it slid there.
  if (model.contact.enabled) {
    State probe = settled;
    find_touching_pairs(model, probe);
    if (!probe.object_contact.touching.empty()) {
      return "contact between objects: where a body rests on another depends on how it slid "
             "there";
    }
  }
  bool can_yield = false;
  for (const SpringKind* kind : kSpringKinds) {
    can_yield = can_yield || kind->yields(model);
  }
  if (!can_yield && !model.can_tear()) {
    return {};
  }
  // The step's own evaluation at the equilibrium, on a copy: does a spring flow or a bar break?
  State probe = settled;
  if (model.can_tear()) {
    break_overloaded_bars(model, probe);
    if (!probe.broken_bars.empty()) {
      return fmt::format("bar {} would tear under the structure's own weight",
                         probe.broken_bars.front());
    }
  }
  compute_forces(model, quiet, probe, true);
  for (const SpringKind* kind : kSpringKinds) {
    const std::vector<double>& before = settled.*kind->plastic_set;
    const std::vector<double>& after = probe.*kind->plastic_set;
    for (std::size_t s = 0; s < after.size(); ++s) {
      if (after[s] != before[s]) {
        return fmt::format(
            "{} would yield under the structure's own weight (the set they keep "
            "depends on the way there)",
            kind->name());
      }
    }
  }
  return {};
}

[[noreturn]] void report_not_settled(const Model& model, const SettleOutcome& outcome) {
  const Index node = outcome.worst_node;
  const ModelObject& object = model.objects[model.node_object[node]];
  const std::string why_relaxed =
      outcome.fallback.empty()
          ? ""
          : fmt::format(" (relaxed instead of Newton's method: {})", outcome.fallback);
  throw_user_error(
      model.settle.loc,
      "the settling phase did not come to rest within its {:g} s ({} steps){}: the largest "
      "out-of-balance force is still {:.3g} of a node's weight (node {} of object '{}'), above "
      "'settle.residual' {:g}. Give 'settle.duration' more time or 'settle.residual' a larger "
      "value; if it never settles, part of the structure can move without resisting (a "
      "mechanism, a node with too few bars) or the time step is too long for it",
      model.settle.duration, outcome.max_steps, why_relaxed, outcome.residual,
      node - object.first_node, object.name, model.settle.residual);
}

// Newton's way (settle.hpp): true with `settling` at rest and `outcome` filled in; false with
// outcome.fallback saying why relaxation must serve from the start instead.
bool settle_by_newton(const Model& model, double dt, const ForceSwitches& quiet,
                      const std::vector<Vec3>& start, State& settling, SettleOutcome& outcome) {
  outcome.fallback = why_not_static(model);
  if (!outcome.fallback.empty()) {
    return false;
  }
  EquilibriumOptions options{model.settle.residual, kMostNewtonIterations, true};
  EquilibriumOutcome equilibrium = find_equilibrium(model, quiet, options, settling);
  if (!equilibrium.converged && equilibrium.unstable) {
    // It buckles or folds on the way, and where it goes is the path's to decide, which Newton's
    // steps do not follow: relaxation takes it along the path, and at its restarts (each time
    // the out-of-balance force has halved) Newton's method tries to finish from there, a few
    // iterations that must stay in stable shapes; the first that converges ends the relaxation.
    settling = make_state(model, false);
    settling.x = start;
    EquilibriumOptions finish{model.settle.residual, kFinishingIterations, true};
    double tried_at = std::numeric_limits<double>::infinity();
    State finished;
    outcome = relax_to_rest(model, dt, quiet, settling, [&](const State& at) {
      const double residual = relative_residual(model, at).first;
      if (!(residual <= 0.5 * tried_at)) {
        return false;
      }
      tried_at = residual;
      finished = at;
      equilibrium = find_equilibrium(model, quiet, finish, finished);
      return equilibrium.converged;
    });
    if (!outcome.stopped) {  // relaxation got there first, or ran out of time
      outcome.fallback = on_sloping_ground(model, settling)
                             ? kSlopeReason
                             : "it is unstable on the way (it buckles or folds), so relaxation "
                               "takes it along its path; Newton's method did not take over";
      if (!(outcome.residual <= model.settle.residual)) {
        report_not_settled(model, outcome);
      }
      return true;
    }
    settling = std::move(finished);
  }
  outcome.fallback = equilibrium.converged ? why_path_matters(model, quiet, settling)
                     : on_sloping_ground(model, settling)
                         ? kSlopeReason
                         : "Newton's method found no equilibrium: " + equilibrium.failure;
  if (!outcome.fallback.empty()) {
    return false;
  }
  outcome.by_newton = true;
  outcome.newton_iterations = equilibrium.iterations;
  outcome.residual = equilibrium.residual;
  outcome.worst_node = equilibrium.worst_node;
  if (outcome.steps == 0) {
    anchor_nodes_at_rest(model, settling);  // relaxation's steps keep their own
  }
  return true;
}

}  // namespace

void settle_under_gravity(const Model& model, double dt, const ForceSwitches& switches,
                          State& state) {
  if (!model.settle.enabled) {
    return;
  }
  // The same structure with nothing but gravity and the ground acting: fields and wind off,
  // supports where they start, in a state of its own at the state's positions (the model is not
  // copied).
  ForceSwitches quiet = switches;
  quiet.fields = false;
  quiet.wind = false;
  State settling = make_state(model, false);
  settling.x = state.x;
  SettleOutcome outcome;
  if (model.settle.method != SettleMethod::kNewton ||
      !settle_by_newton(model, dt, quiet, state.x, settling, outcome)) {
    std::string fallback = std::move(outcome.fallback);
    settling = make_state(model, false);  // from the start, not from where Newton got
    settling.x = state.x;
    outcome = relax_to_rest(model, dt, quiet, settling);
    outcome.fallback = std::move(fallback);
    if (!(outcome.residual <= model.settle.residual)) {
      report_not_settled(model, outcome);
    }
  }
  outcome.ran = true;
  outcome.step = dt;
  state.settled = outcome;
  // The shape reached, and what the way there left: plastic sets, what broke under its own
  // weight, the ground's anchors. Velocities, time and the energy start afresh at t = 0.
  state.x = std::move(settling.x);
  for_each_state_array(
      [](std::string_view, StateArrayRole role, auto& to, auto& from) {
        if (role == StateArrayRole::kHistory) {
          to = std::move(from);
        }
      },
      state, settling);
}

}  // namespace dinam
