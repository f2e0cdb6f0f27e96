#include "solver/implicit_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "dynamics/energy.hpp"
#include "model/contact_builder.hpp"
#include "model/model.hpp"
#include "solver/step_minimiser.hpp"
#include "solver/step_problem.hpp"
#include "solver/step_scheme.hpp"

namespace dinam {
namespace {

// Halvings of a step before the run gives up, and of them those the error criterion may ask for.
constexpr int kMostSplits = 10;
constexpr int kErrorSplits = 5;
// Sub-steps taken at a level of splitting before a sub-step twice as long is tried again.
constexpr int kTakenBeforeLonger = 2;

double median_bar(const Model& model) {
  std::vector<double> lengths = model.bar_rest_length;
  if (lengths.empty()) {
    return 1.0;
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

}  // namespace

// A step's three concerns: its time scheme (backward Euler or BDF2: the base, the prediction,
// the error, the history), its problem (each force kind's terms, contact, the rebounds and the
// energy ledger) and its minimisation (Newton's method or quasi-Newton, the factorisations).
struct ImplicitIntegrator::Workspace {
  Workspace(const Model& model, ImplicitMinimiser method)
      : problem(model, scheme), minimiser(method), bar(median_bar(model)) {}

  StepScheme scheme;
  StepProblem problem;  // refers to scheme's x_n
  StepMinimiser minimiser;
  double bar;  // m, the median bar
};

namespace {

std::unique_ptr<const Model> softened_ground(const Model& model, const ImplicitOptions& options) {
  if (!options.longest_step || !ImplicitIntegrator::copies_model(model)) {
    return nullptr;  // nothing to soften: the model itself is stepped, not a copy
  }
  auto softened = std::make_unique<Model>(model);
  soften_ground(*softened, kImplicitGroundFrequency / *options.longest_step);
  return softened;
}

}  // namespace

bool ImplicitIntegrator::copies_model(const Model& model) {
  return model.ground.enabled && model.ground.automatic_frequency_squared.has_value();
}

ImplicitIntegrator::ImplicitIntegrator(const Model& model, const ImplicitOptions& options)
    : softened_(softened_ground(model, options)),
      model_(softened_ ? *softened_ : model),
      work_(std::make_unique<Workspace>(model_, options.minimiser)) {}

ImplicitIntegrator::~ImplicitIntegrator() = default;

void ImplicitIntegrator::report_energy(State& state) {
  if (!state.energy_workspace.enabled) {
    return;
  }
  // The objects' penalty where they touch at the start (before a step there are no friction
  // springs), where the report reads it.
  state.object_contact.energy = work_->problem.objects.energy(model_, state);
  state.energy_workspace.last = energy_report(model_, state, state.velocity);
}

void ImplicitIntegrator::advance(State& state, double h, std::int64_t steps) {
  if (h != split_of_h_) {  // the level of splitting found is a share of the step it was found on
    split_of_h_ = h;
    level_ = 0;
    taken_at_level_ = 0;
  }
  for (std::int64_t k = 0; k < steps; ++k) {
    step_adaptively(state, h);
  }
}

void ImplicitIntegrator::step_adaptively(State& state, double h) {
  // Positions within the step in units of its finest split, h/2^kMostSplits, so that the sub-steps
  // end exactly at the step's end: a sub-step of level l is 2^(kMostSplits − l) units, and `done`
  // is always a multiple of the present level's.
  constexpr std::int64_t kWhole = std::int64_t{1} << kMostSplits;
  std::int64_t done = 0;
  while (done < kWhole) {
    stop_if_asked();
    const double sub_step = std::ldexp(h, -level_);
    // Past kErrorSplits halvings only Newton's convergence splits a step: an impact's jump in
    // acceleration is no error that a shorter step would remove.
    if (try_step(state, sub_step, level_ < kErrorSplits)) {
      done += kWhole >> level_;
      taken_at_level_ += 1;
      // Back up a level after kTakenBeforeLonger sub-steps at this one, where the longer
      // sub-step would start here.
      const std::int64_t longer = kWhole >> std::max(level_ - 1, 0);
      if (level_ > 0 && taken_at_level_ >= kTakenBeforeLonger && done % longer == 0) {
        level_ -= 1;
        taken_at_level_ = 0;
      }
      continue;
    }
    if (level_ >= kMostSplits) {
      throw RuntimeError(fmt::format(
          "the implicit integrator found no step at t = {:.6g} s even of {:.3g} s (Newton's "
          "method does not converge there{}); try 'integrator: central_difference'",
          state.time, sub_step,
          model_.contact.enabled ? ", or a node of the contact between objects moves more than "
                                   "half its smallest radius even in so short a step"
                                 : ""));
    }
    stats_.splits += 1;
    level_ += 1;
    taken_at_level_ = 0;
  }
}

bool ImplicitIntegrator::try_step(State& state, double h, bool check_error) {
  Workspace& w = *work_;
  StepScheme& scheme = w.scheme;
  StepProblem& problem = w.problem;
  const Model& model = model_;
  problem.break_bars(model, state);
  scheme.set_base(model, state, h);
  problem.take_loads(model, state, scheme.t_next);
  problem.start_contact(model, state, scheme);
  scheme.predict(model, problem.loads, problem.predicted, state);
  problem.set_potential(model, state, scheme);
  // A step that would carry a node of the contact between objects past the speed envelope even
  // without the forces of the potential is split before it is solved.
  if (problem.past_envelope(model, problem.predicted)) {
    scheme.restore(state);
    return false;
  }
  if (!w.minimiser.minimise(model, state, problem, scheme, w.bar, stats_) ||
      problem.past_envelope(model, state.x)) {
    scheme.restore(state);
    return false;
  }
  const ImplicitStepEnds* ends = problem.measure_ends(model, state, scheme);
  const bool contact_changed = problem.find_contact_change(model, state, scheme.x_start);
  if (!scheme.accept(model, state, check_error, contact_changed, kImplicitErrorShare * w.bar)) {
    scheme.restore(state);
    return false;
  }
  problem.book_and_rebound(model, state, scheme, ends);
  scheme.keep_history(model, state, contact_changed, problem.rebounded);
  stats_.steps += 1;
  if (ends) {
    state.energy_workspace.last = energy_report(model, state, state.velocity);
  }
  for (std::size_t i = 0; i < state.x.size(); ++i) {
    if (!state.x[i].allFinite() || !state.velocity[i].allFinite()) {
      throw RuntimeError(
          fmt::format("the motion diverged at node {} at t = {:.6g} s", i, state.time));
    }
  }
  return true;
}

}  // namespace dinam
