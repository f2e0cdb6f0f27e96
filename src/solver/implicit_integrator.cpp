#include "solver/implicit_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <vector>

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/pin_motion.hpp"
#include "dynamics/tearing.hpp"
#include "model/model.hpp"
#include "solver/ground_restitution.hpp"
#include "solver/implicit_dampers.hpp"
#include "solver/implicit_energy.hpp"
#include "solver/implicit_friction.hpp"
#include "solver/implicit_newton.hpp"
#include "solver/implicit_object_contact.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/potential.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Halvings of a step before the run gives up, and of them those the error criterion may ask for.
constexpr int kMostSplits = 10;
constexpr int kErrorSplits = 5;
// Sub-steps taken at a level of splitting before a sub-step twice as long is tried again.
constexpr int kTakenBeforeLonger = 2;

// The forces that derive from V: springs, gravity and the ground's normal penalty. The friction
// anchors are not updated (compute_static_forces), and no node is marked touching, so no stick
// spring acts. Contact between objects is ImplicitObjectContact's, outside the switches.
ForceSwitches potential_switches() {
  ForceSwitches s;
  s.fields = false;
  s.wind = false;
  s.axial_dampers = false;
  s.global_damping = false;
  s.object_contact = false;
  return s;
}

// The forces outside the potential, one kind at a time: the fields (taken at t_{n+1}) and the
// wind (at x_n, v_n).
ForceSwitches only_fields() {
  ForceSwitches s = ForceSwitches::none();
  s.fields = true;
  return s;
}

ForceSwitches only_wind() {
  ForceSwitches s = ForceSwitches::none();
  s.wind = true;
  return s;
}

double median_bar(const Model& model) {
  std::vector<double> lengths = model.bar_rest_length;
  if (lengths.empty()) {
    return 1.0;
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

}  // namespace

struct ImplicitIntegrator::Workspace {
  FreeDofs dofs;
  Vector mass;  // (dofs)
  StiffnessAssembly assembly;
  PositiveDefiniteSolver solver{kFastestSupernodalFrom};
  std::vector<Eigen::Triplet<double>> damper_triplets;
  double bar = 1.0;        // m, the median bar
  double envelope = 0.0;   // m, the most a node of contact between objects may move in a step
  bool any_yield = false;  // some spring can flow
  std::vector<Vec3> x_start, v_start, predicted, explicit_force, accel_before;
  std::vector<Vec3> field_force, wind_force;  // the parts of explicit_force, for the energy ledger
  bool have_accel = false;
  // BDF2's history: x_{n−1} and v_{n−1}, from the last step taken, of `before_h` (0: none).
  std::vector<Vec3> x_before, v_before;
  double before_h = 0.0;
  // The state each step is solved from: (x_n, v_n) for backward Euler; for BDF2, (4 x_n −
  // x_{n−1})/3 and (4 v_n − v_{n−1})/3, with 2h/3 in the place of h.
  std::vector<Vec3> x_base, v_base;
  ImplicitFriction friction;
  ImplicitObjectContact objects;             // contact between objects and within one
  std::vector<std::uint8_t> touching_start;  // State::contact_touching at x_n
  std::vector<Eigen::Triplet<double>> friction_triplets;
  bool factored = false;  // `solver` holds a factorised Hessian of a step of `factored_h`
  double factored_h = 0.0;
  // Newton's trust region, carried from step to step (implicit_newton.hpp).
  double trust_radius = 0.0;

  // Assembles and factorises the incremental potential's Hessian at state.x: the stiffness as it
  // is, which M/h² makes definite unless a step is long against a buckling structure's
  // instability; else with each element's matrix made definite (a descent still, if slower).
  bool factor(const Model& model, State& state, double h, const SparseMatrix& damping,
              const Vector& inertia) {
    factored = false;
    factored_h = h;
    for (const Definiteness definiteness : {Definiteness::kExact, Definiteness::kProjected}) {
      SparseMatrix system =
          assembly.assemble(model, state, potential_switches(), dofs, definiteness);
      system += damping;
      friction_triplets.clear();
      objects.add_hessian(model, state, dofs, friction_triplets);
      if (!friction.empty()) {
        friction.add_hessian(dofs, state.x, friction_triplets);
      }
      if (!friction_triplets.empty()) {
        SparseMatrix held(dofs.count, dofs.count);
        held.setFromTriplets(friction_triplets.begin(), friction_triplets.end());
        system += held;
      }
      system.diagonal() += inertia;
      if (solver.factorize(system)) {
        factored = true;
        break;
      }
    }
    return factored;
  }
};

ImplicitIntegrator::ImplicitIntegrator(const Model& model)
    : model_(model), work_(std::make_unique<Workspace>()) {
  work_->dofs = free_dofs(model);
  work_->mass = free_masses(model, work_->dofs);
  work_->bar = median_bar(model);
  work_->envelope = contact_envelope(model);
  work_->any_yield =
      model.bars_yield || model.bends_yield || model.torsions_yield || model.clamps_yield;
}

ImplicitIntegrator::~ImplicitIntegrator() = default;

void ImplicitIntegrator::report_energy(State& state) {
  if (!state.energy_workspace.enabled) {
    return;
  }
  // The objects' penalty where they touch at the start (before a step there are no friction
  // springs), where the report reads it.
  state.object_contact.energy = work_->objects.energy(model_, state);
  state.energy_workspace.last = energy_report(model_, state, state.v_half);
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
  const Model& model = model_;
  // Bars strained past their breaking limit at x_n break, with what stands on them, as at the
  // start of a step of central differences (serially, so the same bars on any thread count; a
  // step tried again from the same x_n breaks nothing more).
  if (model.can_tear()) {
    break_overloaded_bars(model, state);
  }
  const FreeDofs& dofs = w.dofs;
  const auto n = static_cast<std::size_t>(model.node_count());
  w.x_start = state.x;
  w.v_start = state.v_half;  // v_n: the implicit integrator keeps full-step velocities there
  const double t_next = state.time + h;

  // BDF2 on M v' = F, x' = v: (3 y_{n+1} − 4 y_n + y_{n−1}) / 2h = y'_{n+1} for y = x and v, which
  // is backward Euler's step of 2h/3 from the base y_b = (4 y_n − y_{n−1})/3. It needs the step
  // before to have been as long as this one; the first step, and one after a split, is backward
  // Euler's.
  const bool two_step = model.implicit_scheme == ImplicitScheme::kBdf2 && w.before_h == h;
  const double hs = two_step ? 2.0 * h / 3.0 : h;  // the step the minimisation takes
  w.x_base = w.x_start;
  w.v_base = w.v_start;
  if (two_step) {
    for (std::size_t i = 0; i < n; ++i) {
      w.x_base[i] = (4.0 * w.x_start[i] - w.x_before[i]) / 3.0;
      w.v_base[i] = (4.0 * w.v_start[i] - w.v_before[i]) / 3.0;
    }
  }

  // The forces outside the potential: the fields, which depend on the time alone, at t_{n+1}, as
  // the scheme takes every force (taken at t_n they lagged a ramped load by a whole step); the
  // wind, which depends on the velocities, at (x_n, v_n). Then the friction springs of the nodes
  // on the ground at x_n.
  state.dt = 0.0;
  const double t_start = state.time;
  state.time = t_next;
  compute_forces(model, only_fields(), state);
  state.time = t_start;
  w.explicit_force = state.force;
  const bool ledger = state.energy_workspace.enabled;
  if (ledger) {
    w.field_force = state.force;
    w.wind_force.assign(n, Vec3::Zero());
  }
  if (!model.wind.faces.empty() || !model.wind.bars.empty()) {
    compute_forces(model, only_wind(), state);
    for (std::size_t i = 0; i < n; ++i) {
      w.explicit_force[i] += state.force[i];
    }
    if (ledger) {
      w.wind_force = state.force;
    }
  }
  w.friction.start_step(model, state);
  w.objects.start_step(model, state);
  // Central differences' own friction, which compute_static_forces applies to the nodes marked
  // touching, is no potential: the solve sees none marked (the marks come back with the step).
  w.touching_start = state.contact_touching;
  std::fill(state.contact_touching.begin(), state.contact_touching.end(), 0);

  // x̂ = x_b + h v_b + h² M⁻¹ F_e (h: the step solved for); driven pins go to their places at
  // t_{n+1}.
  w.predicted.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    w.predicted[i] =
        w.x_base[i] + hs * w.v_base[i] + (hs * hs * model.node_inv_mass[i]) * w.explicit_force[i];
  }
  place_driven_nodes(model, t_next, state);

  // The dampers' Hessian, with the bars' directions at x_n (implicit_dampers.hpp), and α m / h
  // on the diagonal.
  const bool global = model.global_damping > 0.0;
  w.damper_triplets.clear();
  add_damper_hessian(model, state, dofs, w.x_start, hs, w.damper_triplets);
  SparseMatrix damping(dofs.count, dofs.count);
  damping.setFromTriplets(w.damper_triplets.begin(), w.damper_triplets.end());
  // The dampers' pull from supports that move, their ends placed at t_{n+1} above.
  const Vector pinned_damping = pinned_damper_forces(model, state, dofs, w.x_start, w.x_base, hs);

  // The incremental potential's gradient g = M(x − x̂)/h² − F(x) + ∇hD, and the energy E, with
  // the dampers' velocities (x − x_b)/h.
  const ForceSwitches switches = potential_switches();
  const Vector inertia = w.mass / (hs * hs) + (global ? model.global_damping / hs : 0.0) * w.mass;
  const Vector predicted = free_part(dofs, w.predicted);
  const Vector start = free_part(dofs, w.x_base);
  const double alpha = global ? model.global_damping : 0.0;
  auto gradient = [&](Vector& g) {
    compute_static_forces(model, switches, state);
    w.friction.add_forces(state.x, state.force);
    w.objects.add_forces(model, state);
    const Vector x = free_part(dofs, state.x);
    const Vector moved = x - start;
    g = (w.mass / (hs * hs)).cwiseProduct(x - predicted) +
        (alpha / hs) * w.mass.cwiseProduct(moved) - free_part(dofs, state.force) + damping * moved -
        pinned_damping;
  };
  auto energy = [&]() {
    const Vector x = free_part(dofs, state.x);
    const Vector off = x - predicted;
    const Vector moved = x - start;
    return potential_energy(model, state, switches, w.x_start, SpringEnergy::kWithFlow).energy +
           w.friction.energy(state.x) + w.objects.energy(model, state) +
           (0.5 / (hs * hs)) * w.mass.dot(off.cwiseProduct(off)) +
           (0.5 * alpha / hs) * w.mass.dot(moved.cwiseProduct(moved)) +
           0.5 * moved.dot(damping * moved) - pinned_damping.dot(moved);
  };
  auto restore = [&] {
    state.contact_touching = w.touching_start;
    state.x = w.x_start;
    state.v_half = w.v_start;
    state.time = t_next - h;
  };
  // A step that would carry a node of the contact between objects past the speed envelope even
  // without the forces of the potential is split before it is solved.
  if (model.contact.enabled && w.objects.longest_move(model, w.predicted) > w.envelope) {
    restore();
    return false;
  }

  // Newton's method from x̂ (the free nodes; the driven ones are placed).
  for (std::size_t i = 0; i < n; ++i) {
    if (dofs.first_dof[i] >= 0) {
      state.x[i] = w.predicted[i];
    }
  }
  if (w.factored_h != hs) {  // the kept Hessian, and the trust region in its norm, are of another h
    w.factored = false;
    w.trust_radius = 0.0;
  }
  const StepPotential potential{
      .gradient = gradient,
      .energy = energy,
      .factor = [&] { return w.factor(model, state, hs, damping, inertia); },
      .precondition = [&](const Vector& r) { return w.solver.solve(r); },
      .join_new_touches = [&] { return w.friction.join_new_touches(model, w.x_start, state.x); },
      .add_new_touches = [&] { return w.friction.add_new_touches(model, w.x_start, state.x); },
  };
  NewtonCounts counts;
  const bool done = minimise_step(state.x, dofs, w.mass, hs, w.bar, potential, w.factored,
                                  w.trust_radius, counts);
  stats_.iterations += counts.iterations;
  stats_.solve_iterations += counts.solve_iterations;
  stats_.factorizations += counts.factorizations;
  if (!done) {
    restore();
    return false;
  }
  // The speed envelope of contact between objects (implicit_object_contact.hpp), at any depth.
  if (model.contact.enabled && w.objects.longest_move(model, state.x) > w.envelope) {
    restore();
    return false;
  }

  // The step's ends for the energy ledger (implicit_energy.hpp): P, with the friction springs
  // the step ended with, at x_{n+1} and at x_n, and its forces at x_{n+1}.
  std::optional<ImplicitStepEnds> ends;
  if (ledger) {
    ImplicitStepEnds& measured = ends.emplace();
    auto step_potential = [&] {  // P and its friction springs' share, at state.x
      const double ground_friction = w.friction.energy(state.x);
      return std::pair{
          potential_energy(model, state, switches, w.x_start, SpringEnergy::kWithFlow).energy +
              ground_friction + w.objects.energy(model, state),
          ground_friction + w.objects.friction_energy(state.x)};
    };
    Vector g_end;
    gradient(g_end);  // leaves the potential's forces at x_{n+1} in state.force
    measured.potential_force = free_part(dofs, state.force);
    for (std::size_t i = 0; i < n; ++i) {
      if (dofs.first_dof[i] < 0) {  // a pinned node: its support's work
        measured.support_work += state.force[i].dot(w.x_start[i] - state.x[i]);
      }
    }
    std::tie(measured.potential_end, measured.friction_end) = step_potential();
    const std::vector<Vec3> x_end = state.x;
    state.x = w.x_start;
    std::tie(measured.potential_start, measured.friction_start) = step_potential();
    state.x = x_end;
    measured.mass = w.mass;
    measured.x_start = free_part(dofs, w.x_start);
    measured.v_start = free_part(dofs, w.v_start);
    measured.x_base = start;
    measured.v_base = free_part(dofs, w.v_base);
    measured.x_end = free_part(dofs, state.x);
    const Vector moved = measured.x_end - start;
    measured.v_end = moved / hs;
    measured.damper_force =
        -(alpha / hs) * w.mass.cwiseProduct(moved) - damping * moved + pinned_damping;
    measured.field_force = free_part(dofs, w.field_force);
    measured.wind_force = free_part(dofs, w.wind_force);
  }

  // v_{n+1} = (x_{n+1} − x_b)/h; the local error h²/2 |a_{n+1} − a_n|, a_n = (v_{n+1} − v_n)/h
  // over the whole step.
  // A step in which a node meets or leaves the ground has a jump in acceleration that no shorter
  // step would smooth (an impact ends within it): it is not judged, nor is the next against it.
  bool contact_changed = false;
  if (model.ground.enabled) {
    for (std::size_t i = 0; i < n && !contact_changed; ++i) {
      const auto node = static_cast<Index>(i);
      contact_changed = (model.ground.clearance(node, w.x_start[i]) < 0.0) !=
                        (model.ground.clearance(node, state.x[i]) < 0.0);
    }
  }
  contact_changed = w.objects.touching_changed(model, state) || contact_changed;
  double error = 0.0;
  std::vector<Vec3> accel(n, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 v = (state.x[i] - w.x_base[i]) / hs;
    accel[i] = (v - w.v_start[i]) / h;
    if (w.have_accel && !model.pinned(static_cast<Index>(i))) {
      error = std::max(error, 0.5 * h * h * (accel[i] - w.accel_before[i]).norm());
    }
    state.v_half[i] = v;
  }
  if (check_error && !contact_changed && error > kImplicitErrorShare * w.bar) {
    restore();
    return false;
  }
  state.contact_touching = w.touching_start;
  if (ends) {
    const EnergyAccounts step = implicit_step_accounts(*ends);
    state.energy.add_works(step, 1.0);
    state.energy.numerical_dissipation += step.numerical_dissipation;
  }
  // The nodes that landed leave with the ground's restitution (ground_restitution.hpp), and the
  // pairs of primitives that met with the contact's (implicit_object_contact.hpp); BDF2's history
  // then starts again, its velocity before the impact being no longer the motion's. The energy
  // the rebound gives back is the scheme's: backward Euler's step into the penalty took it.
  const double kinetic_before = ends ? kinetic_energy(model, state.v_half) : 0.0;
  const bool landed = rebound_landing_nodes(model, w.x_start, w.v_start, state);
  const bool rebounded = w.objects.rebound_pairs(model, w.v_start, h, state) || landed;
  if (ends) {
    state.energy.numerical_dissipation -= kinetic_energy(model, state.v_half) - kinetic_before;
  }
  w.friction.finish_step(model, state);
  w.objects.finish_step(model, h, state);
  if (w.any_yield) {
    // The springs that flowed keep their new plastic sets (the return mapping at x_{n+1}).
    ForceSwitches springs = potential_switches();
    springs.gravity = springs.ground = false;
    const std::vector<Vec3> velocities = state.v_half;
    compute_forces(model, springs, state, true);
    state.v_half = velocities;
  }
  w.accel_before = std::move(accel);
  w.have_accel = !contact_changed;
  if (model.implicit_scheme == ImplicitScheme::kBdf2) {
    w.x_before = w.x_start;
    w.v_before = w.v_start;
    w.before_h = rebounded ? 0.0 : h;
  }
  state.time = t_next;
  state.step += 1;
  stats_.steps += 1;
  if (ends) {
    state.energy_workspace.last = energy_report(model, state, state.v_half);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!state.x[i].allFinite() || !state.v_half[i].allFinite()) {
      throw RuntimeError(
          fmt::format("the motion diverged at node {} at t = {:.6g} s", i, state.time));
    }
  }
  return true;
}

}  // namespace dinam
