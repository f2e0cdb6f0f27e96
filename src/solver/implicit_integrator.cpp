#include "solver/implicit_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>
#include <vector>

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "dynamics/contact/ground_friction_implicit.hpp"
#include "dynamics/contact/ground_restitution.hpp"
#include "dynamics/contact/object_contact_implicit.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/pin_motion.hpp"
#include "dynamics/tearing.hpp"
#include "model/contact_builder.hpp"
#include "model/model.hpp"
#include "solver/constant_system.hpp"
#include "solver/implicit_energy.hpp"
#include "solver/implicit_newton.hpp"
#include "solver/incremental_potential.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/potential.hpp"
#include "solver/quasi_newton.hpp"
#include "solver/stiffness_matrix.hpp"
#include "solver/triplet_matrix.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Halvings of a step before the run gives up, and of them those the error criterion may ask for.
constexpr int kMostSplits = 10;
constexpr int kErrorSplits = 5;
// Sub-steps taken at a level of splitting before a sub-step twice as long is tried again.
constexpr int kTakenBeforeLonger = 2;

// The springs alone, whose plastic sets a step's end moves on.
ForceSwitches spring_switches() {
  ForceSwitches switches = ForceSwitches::none();
  for (const ForceKind* kind : kForceKinds) {
    switches.*kind->switched = kind->spring != nullptr;
  }
  return switches;
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
  // The parts of explicit_force, load by load in the order of kForceKinds (empty for the other
  // kinds), for the energy ledger.
  std::array<std::vector<Vec3>, kForceKinds.size()> load_forces;
  bool have_accel = false;
  // BDF2's history: x_{n−1} and v_{n−1}, from the last step taken, of `before_h` (0: none).
  std::vector<Vec3> x_before, v_before;
  double before_h = 0.0;
  // The state each step is solved from: (x_n, v_n) for backward Euler; for BDF2, (4 x_n −
  // x_{n−1})/3 and (4 v_n − v_{n−1})/3, with 2h/3 in the place of h.
  std::vector<Vec3> x_base, v_base;
  ImplicitFriction friction;
  ImplicitObjectContact objects;  // contact between objects and within one
  TripletMatrix dampers;          // D, the dampers' Hessian
  IncrementalPotential potential{dofs, mass, x_start, friction, objects};
  NewtonWorkspace newton;
  std::vector<Eigen::Triplet<double>> friction_triplets;
  TripletMatrix held;     // the friction springs' Hessian, from friction_triplets
  SparseMatrix system;    // the Hessian factorised last
  bool factored = false;  // `solver` holds a factorised Hessian of a step of `factored_h`
  double factored_h = 0.0;
  // Newton's trust region, carried from step to step (implicit_newton.hpp).
  double trust_radius = 0.0;

  // Assembles and factorises the incremental potential's Hessian at state.x: the stiffness as it
  // is, which M/h² makes definite unless a step is long against a buckling structure's
  // instability; else with each element's matrix made definite (a descent still, if slower).
  bool factor(const Model& model, State& state, double step, const SparseMatrix& damping,
              const Vector& inertia) {
    factored = false;
    factored_h = step;
    for (const Definiteness definiteness : {Definiteness::kExact, Definiteness::kProjected}) {
      system = assembly.assemble(model, state, potential_switches(), dofs, definiteness);
      add_sparse(system, damping);
      friction_triplets.clear();
      objects.add_hessian(model, state, dofs, friction_triplets);
      if (!friction.empty()) {
        friction.add_hessian(dofs, state.x, friction_triplets);
      }
      if (!friction_triplets.empty()) {
        add_sparse(system, held.set(dofs.count, friction_triplets));
      }
      system.diagonal() += inertia;
      if (solver.factorize(system)) {
        factored = true;
        break;
      }
    }
    return factored;
  }

  // The step being tried: its length h, the length hs the minimisation takes (2h/3 for BDF2's
  // two-step steps) and the time it ends at.
  double h = 0.0;
  double hs = 0.0;
  double t_next = 0.0;

  // 1. Bars strained past their breaking limit at x_n break, with what stands on them, as at the
  // start of a step of central differences (serially, so the same bars on any thread count; a
  // step tried again from the same x_n breaks nothing more).
  void break_bars(const Model& model, State& state) const {
    if (model.can_tear()) {
      break_overloaded_bars(model, state);
    }
  }

  // 2. The state the step is solved from. BDF2 on M v' = F, x' = v: (3 y_{n+1} − 4 y_n +
  // y_{n−1}) / 2h = y'_{n+1} for y = x and v, which is backward Euler's step of 2h/3 from the base
  // y_b = (4 y_n − y_{n−1})/3. It needs the step before to have been as long as this one; the
  // first step, and one after a split, is backward Euler's.
  void set_base(const Model& model, const State& state, double step) {
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

  // 3. The forces outside the potential, kind by kind (force_kinds.hpp), each taken as a load: one
  // of the time alone (the fields) at t_{n+1}, as the scheme takes every force (taken at t_n they
  // lagged a ramped load by a whole step); one that depends on the motion (the wind) at (x_n,
  // v_n). While the energy is tracked each one's own forces are kept for its work.
  void take_loads(const Model& model, State& state) {
    const std::size_t n = state.x.size();
    explicit_force.assign(n, Vec3::Zero());
    for (std::size_t k = 0; k < kForceKinds.size(); ++k) {
      const ForceKind& kind = *kForceKinds[k];
      const bool at_end = kind.implicit == ImplicitTreatment::kLoadAtEnd;
      if ((!at_end && kind.implicit != ImplicitTreatment::kLoadAtStart) ||
          !kind.acts_in(model, ForceSwitches{})) {
        continue;
      }
      compute_forces_at(model, only(kind), state, at_end ? t_next : state.time);
      for (std::size_t i = 0; i < n; ++i) {
        explicit_force[i] += state.force[i];
      }
      if (state.energy_workspace.enabled) {
        load_forces[k] = state.force;
      }
    }
  }

  // 4. The friction springs of the nodes on the ground, and the contact between objects, at x_n.
  // (Central differences' own friction is no potential: the step's potential forces leave it out.)
  void start_contact(const Model& model, State& state) {
    friction.start_step(model, state);
    objects.start_step(model, state);
  }

  // While the energy is tracked, P at x_n (the springs, gravity and the ground's penalty, as the
  // step holds them) for the ledger (measure_ends), before the driven pins move.
  void weigh_start(const Model& model, const State& state) {
    if (state.energy_workspace.enabled) {
      potential_at_start =
          potential_energy(model, state, potential.switches, x_start, SpringEnergy::kWithFlow)
              .energy;
    }
  }

  // 5. x̂ = x_b + h v_b + h² M⁻¹ F_e (h: the step solved for); driven pins go to their places at
  // t_{n+1}.
  void predict(const Model& model, State& state) {
    const std::size_t n = state.x.size();
    predicted.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      predicted[i] =
          x_base[i] + hs * v_base[i] + (hs * hs * model.node_inv_mass[i]) * explicit_force[i];
    }
    place_driven_nodes(model, t_next, state);
  }

  // 6. The incremental potential of this step: each damper kind's dissipation (its ImplicitDamper,
  // force_kind.hpp: the bars' along their directions at x_n, the global damping's α m / h on the
  // diagonal) and its pull from supports that move, their ends placed at t_{n+1} above.
  void set_potential(const Model& model, State& state) {
    potential.model = &model;
    potential.state = &state;
    potential.hs = hs;
    potential.alpha = 0.0;
    damper_triplets.clear();
    potential.pinned_damping.setZero(dofs.count);
    for (const ForceKind* kind : kForceKinds) {
      const ImplicitDamper& damper = kind->damper;
      if (kind->implicit != ImplicitTreatment::kDamper || !kind->acts_in(model, ForceSwitches{})) {
        continue;
      }
      if (damper.mass_rate != nullptr) {
        potential.alpha += damper.mass_rate(model);
      }
      if (damper.add_hessian != nullptr) {
        damper.add_hessian(model, state, dofs, x_start, hs, damper_triplets);
      }
      if (damper.add_support_pull != nullptr) {
        damper.add_support_pull(model, state, dofs, x_start, x_base, hs, potential.pinned_damping);
      }
    }
    potential.damping = &dampers.set(dofs.count, damper_triplets);
    potential.inertia = mass / (hs * hs) + (potential.alpha / hs) * mass;
    free_part(dofs, predicted, potential.predicted);
    free_part(dofs, x_base, potential.start);
  }

  // Whether positions `x` carry a node of the contact between objects past the speed envelope
  // (object_contact_implicit.hpp).
  bool past_envelope(const Model& model, const std::vector<Vec3>& x) {
    return model.contact.enabled && objects.longest_move(model, x) > envelope;
  }

  // The state as it was before the step was tried.
  void restore(State& state) const {
    state.x = x_start;
    state.velocity = v_start;
    state.time = t_next - h;
  }

  // 7a. Where Newton's method starts: x̂, or after a step that ended with a rebound, x̂ less the
  // rebound's velocities (x̂ + h (v_unbounced − v_n)) where its energy is lower. A node kicked
  // alone out of a stiff piece (ground_restitution.hpp) has an x̂ a rebound's h v away from its
  // neighbours, across bars a fraction of that long: its bars' energy there dwarfs the inertia's,
  // and Newton's method, in a trust region over a landscape far from quadratic, crawled back
  // (25 iterations a step, split after split, for a letter of assimp's collada.ogex landing flat;
  // 4 times the run). x̂ is still the step's inertia target, so the step solves the same
  // equations, and a loose node, whose x̂ is lower, still starts there and bounces.
  void place_start(State& state) {
    for (std::size_t i = 0; i < state.x.size(); ++i) {
      if (dofs.first_dof[i] >= 0) {
        state.x[i] = predicted[i];
      }
    }
    if (!rebounded) {
      return;
    }
    const double at_prediction = potential.energy();
    unbounced_start.assign(state.x.begin(), state.x.end());
    for (std::size_t i = 0; i < state.x.size(); ++i) {
      if (dofs.first_dof[i] >= 0) {
        unbounced_start[i] += hs * (v_unbounced[i] - v_base[i]);
      }
    }
    std::swap(state.x, unbounced_start);
    if (potential.energy() >= at_prediction) {
      std::swap(state.x, unbounced_start);
    }
  }

  // 7b'. Or quasi-Newton about a constant matrix (quasi_newton.hpp), where the options ask.
  ImplicitMinimiser minimiser = ImplicitMinimiser::kNewton;
  ConstantSystem constant;
  double constant_h = 0.0;
  QuasiNewtonWorkspace quasi;
  bool minimise_quasi(const Model& model, State& state, ImplicitStats& stats) {
    place_start(state);
    if (!constant.has_springs()) {
      constant.set_springs(model, state, dofs);
    }
    if (constant_h != hs) {
      if (!constant.factor(potential.inertia, *potential.damping)) {
        return false;
      }
      constant_h = hs;
      quasi.forget();
      stats.factorizations += 1;
    }
    auto gradient = [&](Vector& g) { potential.gradient(g); };
    auto energy = [&] { return potential.energy(); };
    auto no_factor = [] { return false; };
    auto precondition = [&](const Vector& r, Vector& solved) { constant.solve(r, solved); };
    auto join_new_touches = [&] { return friction.join_new_touches(model, x_start, state.x); };
    auto add_new_touches = [&] { return friction.add_new_touches(model, x_start, state.x); };
    const StepPotential step{
        .gradient = gradient,
        .energy = energy,
        .factor = no_factor,
        .precondition = precondition,
        .join_new_touches = join_new_touches,
        .add_new_touches = add_new_touches,
    };
    QuasiNewtonCounts counts;
    const bool done = minimise_quasi_newton(state.x, dofs, mass, hs, bar, step, counts, quasi);
    stats.iterations += counts.iterations;
    stats.solve_iterations += counts.energies;
    return done;
  }

  // 7b. Newton's method from there (the free nodes; the driven ones are placed); false where it
  // did not converge.
  bool minimise(const Model& model, State& state, ImplicitStats& stats) {
    if (minimiser == ImplicitMinimiser::kQuasiNewton) {
      return minimise_quasi(model, state, stats);
    }
    place_start(state);
    if (factored_h != hs) {  // the kept Hessian, and the trust region in its norm, are of another h
      factored = false;
      trust_radius = 0.0;
    }
    auto gradient = [&](Vector& g) { potential.gradient(g); };
    auto energy = [&] { return potential.energy(); };
    auto factor_here = [&] {
      return factor(model, state, hs, *potential.damping, potential.inertia);
    };
    auto precondition = [&](const Vector& r, Vector& solved) { solver.solve(r, solved); };
    auto join_new_touches = [&] { return friction.join_new_touches(model, x_start, state.x); };
    auto add_new_touches = [&] { return friction.add_new_touches(model, x_start, state.x); };
    const StepPotential step{
        .gradient = gradient,
        .energy = energy,
        .factor = factor_here,
        .precondition = precondition,
        .join_new_touches = join_new_touches,
        .add_new_touches = add_new_touches,
    };
    NewtonCounts counts;
    const bool done =
        minimise_step(state.x, dofs, mass, hs, bar, step, factored, trust_radius, counts, newton);
    stats.iterations += counts.iterations;
    stats.solve_iterations += counts.solve_iterations;
    stats.factorizations += counts.factorizations;
    return done;
  }

  // 8. The step's ends for the energy ledger (implicit_energy.hpp), while it is kept: P, with the
  // friction springs the step ended with, at x_{n+1} and at x_n (weigh_start's share and the
  // friction's, from x_n kept: the state stays at x_{n+1}), and its forces at x_{n+1}. Null while
  // the energy is not tracked.
  const ImplicitStepEnds* measure_ends(const Model& model, State& state) {
    if (!state.energy_workspace.enabled) {
      return nullptr;
    }
    ImplicitStepEnds& measured = step_ends;
    auto step_potential = [&] {  // P and its friction springs' share, at state.x
      const double ground_friction = friction.energy(state.x);
      return std::pair{
          potential_energy(model, state, potential.switches, x_start, SpringEnergy::kWithFlow)
                  .energy +
              ground_friction + objects.energy(model, state),
          ground_friction + objects.friction_energy(state.x)};
    };
    potential.gradient(newton.g_moved);  // leaves the potential's forces at x_{n+1} in state.force
    free_part(dofs, state.force, measured.potential_force);
    measured.support_work = 0.0;
    for (std::size_t i = 0; i < state.x.size(); ++i) {
      if (dofs.first_dof[i] < 0) {  // a pinned node: its support's work
        measured.support_work += state.force[i].dot(x_start[i] - state.x[i]);
      }
    }
    std::tie(measured.potential_end, measured.friction_end) = step_potential();
    const double ground_friction_start = friction.energy(x_start);
    measured.potential_start =
        potential_at_start + ground_friction_start + objects.energy_at_start(model);
    measured.friction_start = ground_friction_start + objects.friction_energy(x_start);
    measured.mass = mass;
    free_part(dofs, x_start, measured.x_start);
    free_part(dofs, v_start, measured.v_start);
    measured.x_base = potential.start;
    free_part(dofs, v_base, measured.v_base);
    free_part(dofs, state.x, measured.x_end);
    potential.moved = measured.x_end - potential.start;
    const Vector& moved = potential.moved;
    measured.v_end = moved / hs;
    potential.damped.noalias() = *potential.damping * moved;
    measured.damper_force = -(potential.alpha / hs) * mass.cwiseProduct(moved) - potential.damped +
                            potential.pinned_damping;
    std::size_t loads = 0;
    for (std::size_t k = 0; k < kForceKinds.size(); ++k) {
      if (!load_forces[k].empty()) {
        if (loads == measured.loads.size()) {
          measured.loads.emplace_back();
        }
        ImplicitStepEnds::Load& load = measured.loads[loads++];
        load.work = kForceKinds[k]->ledger[0].work;
        free_part(dofs, load_forces[k], load.force);
      }
    }
    measured.loads.resize(loads);
    return &measured;
  }

  // 9. v_{n+1} = (x_{n+1} − x_b)/h; the local error h²/2 |a_{n+1} − a_n|, a_n = (v_{n+1} − v_n)/h
  // over the whole step: false (to be split) where, with `check_error`, it passes
  // kImplicitErrorShare of the median bar. A step in which a node meets or leaves the ground has
  // a jump in acceleration that no shorter step would smooth (an impact ends within it): it is
  // not judged, nor is the next against it.
  bool accept(const Model& model, State& state, bool check_error) {
    const std::size_t n = state.x.size();
    contact_changed = false;
    if (model.ground.enabled) {
      for (std::size_t i = 0; i < n && !contact_changed; ++i) {
        const auto node = static_cast<Index>(i);
        contact_changed = (model.ground.clearance(node, x_start[i]) < 0.0) !=
                          (model.ground.clearance(node, state.x[i]) < 0.0);
      }
    }
    contact_changed = objects.touching_changed(model, state) || contact_changed;
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
    return !(check_error && !contact_changed && error > kImplicitErrorShare * bar);
  }

  // 10. The step kept: its works booked; the nodes that landed leave with the ground's
  // restitution (ground_restitution.hpp), and the pairs of primitives that met with the
  // contact's (object_contact_implicit.hpp). The energy the rebound gives back is the scheme's:
  // backward Euler's step into the penalty took it. The springs that flowed keep their new
  // plastic sets (the return mapping at x_{n+1}).
  void book_and_rebound(const Model& model, State& state, const ImplicitStepEnds* ends) {
    if (ends) {
      const EnergyAccounts step = implicit_step_accounts(*ends);
      state.energy.add_works(step, 1.0);
      state.energy.numerical_dissipation += step.numerical_dissipation;
    }
    const double kinetic_before = ends ? kinetic_energy(model, state.velocity) : 0.0;
    v_unbounced = state.velocity;
    const bool landed = rebound_landing_nodes(model, x_start, v_start, state);
    rebounded = objects.rebound_pairs(model, v_start, h, state) || landed;
    if (ends) {
      state.energy.numerical_dissipation -= kinetic_energy(model, state.velocity) - kinetic_before;
    }
    friction.finish_step(model, state);
    objects.finish_step(model, h, state);
    if (any_yield) {
      compute_forces(model, spring_switches(), state, true);
    }
  }

  // 11. What the next step is judged and based on: this step's accelerations, and BDF2's history,
  // which starts again after a rebound (the velocity before the impact is no longer the
  // motion's). The state moves on to t_{n+1}.
  void keep_history(const Model& model, State& state) {
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

  std::vector<Vec3> accel;  // this step's accelerations, while it is judged
  // P at x_n (weigh_start) and the step's ends (measure_ends), while the energy is tracked.
  double potential_at_start = 0.0;
  ImplicitStepEnds step_ends;
  bool contact_changed = false;  // a node met or left the ground, or a pair touched or parted
  bool rebounded = false;        // a node or a pair of the contact rebounded
  // The last step's velocities before its rebounds, and the start they would give (place_start).
  std::vector<Vec3> v_unbounced, unbounced_start;
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
      work_(std::make_unique<Workspace>()) {
  work_->minimiser = options.minimiser;
  work_->dofs = free_dofs(model_);
  work_->mass = free_masses(model_, work_->dofs);
  work_->bar = median_bar(model_);
  work_->envelope = contact_envelope(model_);
  work_->any_yield = std::any_of(kSpringKinds.begin(), kSpringKinds.end(),
                                 [&](const SpringKind* kind) { return kind->yields(model_); });
}

ImplicitIntegrator::~ImplicitIntegrator() = default;

void ImplicitIntegrator::report_energy(State& state) {
  if (!state.energy_workspace.enabled) {
    return;
  }
  // The objects' penalty where they touch at the start (before a step there are no friction
  // springs), where the report reads it.
  state.object_contact.energy = work_->objects.energy(model_, state);
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
  const Model& model = model_;
  w.break_bars(model, state);
  w.set_base(model, state, h);
  w.take_loads(model, state);
  w.start_contact(model, state);
  w.weigh_start(model, state);
  w.predict(model, state);
  w.set_potential(model, state);
  // A step that would carry a node of the contact between objects past the speed envelope even
  // without the forces of the potential is split before it is solved.
  if (w.past_envelope(model, w.predicted)) {
    w.restore(state);
    return false;
  }
  if (!w.minimise(model, state, stats_) || w.past_envelope(model, state.x)) {
    w.restore(state);
    return false;
  }
  const ImplicitStepEnds* ends = w.measure_ends(model, state);
  if (!w.accept(model, state, check_error)) {
    w.restore(state);
    return false;
  }
  w.book_and_rebound(model, state, ends);
  w.keep_history(model, state);
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
