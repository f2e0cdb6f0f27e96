#include "solver/implicit_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

#include "core/error.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/pin_motion.hpp"
#include "dynamics/tearing.hpp"
#include "model/model.hpp"
#include "solver/ground_restitution.hpp"
#include "solver/implicit_dampers.hpp"
#include "solver/implicit_energy.hpp"
#include "solver/implicit_friction.hpp"
#include "solver/implicit_object_contact.hpp"
#include "solver/line_search.hpp"
#include "solver/positive_definite_solver.hpp"
#include "solver/potential.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Newton iterations a step may take before it is split.
constexpr int kMostIterations = 25;
// Halvings of a step before the run gives up, and of them those the error criterion may ask for.
constexpr int kMostSplits = 10;
constexpr int kErrorSplits = 5;
// A step is found once a Newton step has been taken and either the out-of-balance force left
// would move no node by more than this share of the median bar within the step (|g_i| h²/m_i), or
// a whole Newton step moved none by more: far below what can be seen, far above rounding. (The
// second test is the one a node pressed on the ground meets: the ground's stiffness, not its
// mass, sets how far its residual force moves it.) Neither share may stand for an out-of-balance
// acceleration above kConvergedAcceleration: the error each step leaves is a velocity error of
// |g|h/m, and the motion's over a second is their sum, so on short steps (a pendulum of one
// 1 m bar at 2.5 ms steps allowed 1.6 m/s² and lost half its swing in two periods) the bar's
// share would allow too much. (1e-3 of g: over 3 s at most 3 cm/s of drift; the pendulum then
// keeps its swing to 0.5 mm at 2.5 ms. 1e-4 of g made the Wuson's first 0.5 s take a third
// longer, for no difference to be seen.)
constexpr double kConvergedShare = 1e-5;
constexpr double kConvergedAcceleration = 1e-2;  // m/s²
// The line search's least step length before the step is split instead (its sufficient decrease
// is the equilibrium's: line_search.hpp).
constexpr double kLeastLength = 1.0 / 1024;
// The Newton step's linear solve (conjugate gradients preconditioned with the kept factorisation):
// the share of the gradient its residual is cut to, and the iterations it may take before the
// Hessian is factorised again. (An iteration costs a solve with the factor and a force
// evaluation, about 1.3 ms on the Wuson; a factorisation 60 to 130 ms.)
constexpr double kForcing = 0.01;
constexpr int kMostSolveIterations = 30;
// Times a step's solve goes on with the friction of nodes that landed within it
// (ImplicitFriction::add_new_touches): a node that lands where the last round had it above the
// plane needs another.
constexpr int kMostLandingRounds = 3;

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
  PositiveDefiniteSolver solver;
  std::vector<Eigen::Triplet<double>> damper_triplets;
  double bar = 1.0;        // m, the median bar
  double envelope = 0.0;   // m, the most a node of contact between objects may move in a step
  bool any_yield = false;  // some spring can flow
  std::vector<Vec3> x_start, v_start, predicted, explicit_force, accel_before, x_iterate;
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
  for (std::int64_t k = 0; k < steps; ++k) {
    step_or_split(state, h, 0);
  }
}

void ImplicitIntegrator::step_or_split(State& state, double h, int depth) {
  // Past kErrorSplits halvings only Newton's convergence splits a step: an impact's jump in
  // acceleration is no error that a shorter step would remove.
  if (try_step(state, h, depth < kErrorSplits)) {
    return;
  }
  if (depth >= kMostSplits) {
    throw RuntimeError(fmt::format(
        "the implicit integrator found no step at t = {:.6g} s even of {:.3g} s (Newton's method "
        "does not converge there{}); try 'integrator: central_difference'",
        state.time, h,
        model_.contact.enabled ? ", or a node of the contact between objects moves more than "
                                 "half its smallest radius even in so short a step"
                               : ""));
  }
  stats_.splits += 1;
  step_or_split(state, 0.5 * h, depth + 1);
  step_or_split(state, 0.5 * h, depth + 1);
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
        (alpha / hs) * w.mass.cwiseProduct(moved) - free_part(dofs, state.force) + damping * moved;
  };
  auto energy = [&]() {
    const Vector x = free_part(dofs, state.x);
    const Vector off = x - predicted;
    const Vector moved = x - start;
    return potential_energy(model, state, switches, w.x_start, SpringEnergy::kWithFlow).energy +
           w.friction.energy(state.x) + w.objects.energy(model, state) +
           (0.5 / (hs * hs)) * w.mass.dot(off.cwiseProduct(off)) +
           (0.5 * alpha / hs) * w.mass.dot(moved.cwiseProduct(moved)) +
           0.5 * moved.dot(damping * moved);
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
  const double converged =  // m/s², a node's |g|/m
      std::min(kConvergedShare * w.bar / (hs * hs), kConvergedAcceleration);
  const double small_step = converged * hs * hs;  // m
  Vector g;
  gradient(g);
  double e = energy();
  bool done = false;
  // The largest out-of-balance acceleration of a residual, m/s²: what convergence is judged by.
  auto worst_of = [&](const Vector& r) {
    double worst = 0.0;
    for (Index d = 0; d < dofs.count; ++d) {
      worst = std::max(worst, std::abs(r[d]) / w.mass[d]);
    }
    return worst;
  };
  // H v, the incremental potential's Hessian at state.x along v, from the gradient there (`g`)
  // and at state.x + ε v: exact for the inertia and dampers, and to about 1e-7 for the springs
  // (the difference step, √(rounding × extent × bar), balances the gradient's rounding against
  // the springs' curvature over the step).
  double extent = 1.0;
  for (const Vec3& x : state.x) {
    extent = std::max(extent, x.lpNorm<Eigen::Infinity>());
  }
  const double difference_step =
      std::sqrt(std::numeric_limits<double>::epsilon() * extent * w.bar);  // m
  Vector g_moved;
  auto hessian_times = [&](const Vector& v, Vector& product) {
    double furthest = 0.0;
    for (Index d = 0; d < dofs.count; d += 3) {
      furthest = std::max(furthest, v.segment<3>(d).norm());
    }
    if (furthest == 0.0) {
      product.setZero(dofs.count);
      return;
    }
    const double epsilon = difference_step / furthest;
    w.x_iterate = state.x;
    for (std::size_t i = 0; i < n; ++i) {
      const Index d = dofs.first_dof[i];
      if (d >= 0) {
        state.x[i] += epsilon * Vec3(v.segment<3>(d));
      }
    }
    gradient(g_moved);
    state.x = w.x_iterate;
    product = (g_moved - g) / epsilon;
  };
  // The Newton step s, H s = −g, by conjugate gradients preconditioned with the kept factorised
  // Hessian P (an earlier iterate's or step's; exactly H for a linear problem, where the first
  // iteration is the whole step). A node that met the ground or a spring that turned since P was
  // factorised is an eigenvalue of P⁻¹H away from 1, which costs the solve an iteration or two,
  // where factorising again costs dozens. Stops once the residual is kForcing of g's (an inexact
  // Newton step, which still converges fast) or below half the convergence tolerance; at a
  // direction of negative curvature (the structure is unstable there: the step so far still goes
  // downhill, and the first iteration's P⁻¹(−g) does, P being positive definite); or after
  // kMostSolveIterations, where P no longer describes H and is factorised again at the next
  // iterate. `solved`: the step is Newton's to the tolerance.
  struct NewtonStep {
    Vector step;
    bool solved = false;
    bool exhausted = false;  // stopped at kMostSolveIterations
  };
  Vector residual, preconditioned, direction, product;
  auto newton_step = [&]() {
    NewtonStep result;
    result.step.setZero(dofs.count);
    residual = -g;
    const double target = std::max(kForcing * worst_of(g), 0.5 * converged);
    // Nothing out of balance at all (a body in free flight without gravity, where x̂ is exact):
    // the step is zero, and solved. (A residual however small is solved for: a slow motion would
    // otherwise stop where x̂ put it.)
    if (worst_of(residual) == 0.0) {
      result.solved = true;
      return result;
    }
    preconditioned = w.solver.solve(residual);
    direction = preconditioned;
    double along = residual.dot(preconditioned);
    for (int k = 0; k < kMostSolveIterations; ++k) {
      stats_.solve_iterations += 1;
      hessian_times(direction, product);
      const double curvature = direction.dot(product);
      if (!(curvature > 0.0)) {
        if (k == 0) {
          result.step = direction;
        }
        return result;
      }
      const double length = along / curvature;
      result.step += length * direction;
      residual -= length * product;
      if (worst_of(residual) <= target) {
        result.solved = true;
        return result;
      }
      preconditioned = w.solver.solve(residual);
      const double along_next = residual.dot(preconditioned);
      direction = preconditioned + (along_next / along) * direction;
      along = along_next;
    }
    result.exhausted = true;
    return result;
  };
  // The factorised Hessian is kept from iterate to iterate and from step to step (assembling and
  // factorising it costs far more than a force), and factorised again where the solve above
  // exhausts its iterations, where a step with it finds no descent, and where h changes.
  // `fresh`: it was factorised at this iterate.
  bool fresh = false;
  auto factor_here = [&] {
    stats_.factorizations += 1;
    fresh = true;
    return w.factor(model, state, hs, damping, inertia);
  };
  if (w.factored_h != hs) {
    w.factored = false;
  }
  // Found, unless a node landed within the step: then its friction joins and the step goes on.
  int landings = 0;
  auto found = [&] {
    if (landings < kMostLandingRounds && w.friction.add_new_touches(model, w.x_start, state.x)) {
      landings += 1;
      gradient(g);
      e = energy();
      return false;
    }
    return true;
  };
  for (int iteration = 0; iteration < kMostIterations && !done; ++iteration) {
    // At least one Newton step: from x̂ alone a slow motion would pass the test unsolved (a
    // linear step is exact after one).
    if (iteration > 0 && worst_of(g) <= converged && found()) {
      done = true;
      break;
    }
    stats_.iterations += 1;
    if (!w.factored && !factor_here()) {
      break;
    }
    const NewtonStep newton = newton_step();
    const Vector& step = newton.step;
    double largest = 0.0;  // m, the step's longest move of a node
    for (Index d = 0; d < dofs.count; d += 3) {
      largest = std::max(largest, step.segment<3>(d).norm());
    }
    const double slope = g.dot(step);  // < 0 for a descent direction
    // No descent left to take, and none needed (a structure at rest with nothing moving it: the
    // gradient is zero and so is the step).
    if (slope >= 0.0 && newton.solved && largest <= small_step && found()) {
      done = true;
      break;
    }
    const std::vector<Vec3> from = state.x;
    double length = 1.0;
    bool accepted = false;
    while (slope < 0.0 && length >= kLeastLength) {
      for (std::size_t i = 0; i < n; ++i) {
        const Index d = dofs.first_dof[i];
        if (d >= 0) {
          state.x[i] = from[i] + length * Vec3(step.segment<3>(d));
        }
      }
      const double trial = energy();
      if (trial <= e + kSufficientDecrease * length * slope ||
          std::abs(trial - e) <= kEnergyRounding * std::abs(e)) {
        e = trial;
        accepted = true;
        break;
      }
      length *= 0.5;
    }
    if (!accepted) {
      state.x = from;
      // A step this short that lowers no energy the rounding can see: the residual left is
      // rounding's (a stiff bar's axial force, to a fraction of a picometre), not an unsolved step.
      if (newton.solved && largest <= small_step) {
        done = found();
        if (done) {
          break;
        }
        continue;  // a node landed: solve on with its friction
      }
      if (fresh) {
        break;  // not even the Hessian of this iterate gives a step: split it
      }
      w.factored = false;  // a kept Hessian: factorise it here and try again
      continue;
    }
    // Nodes that went below the plane with this step hold by friction from the next iterate on,
    // rather than only once the step has converged without them (which restarted the
    // convergence, once for every round of landings).
    if (w.friction.join_new_touches(model, w.x_start, state.x)) {
      e = energy();
    }
    gradient(g);
    // A whole Newton step that moved no node further than `small_step`: the next would move them
    // far less.
    if (length == 1.0 && largest <= small_step && newton.solved && found()) {
      done = true;
      break;
    }
    fresh = false;
    if (newton.exhausted) {
      w.factored = false;
    }
  }
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
    gradient(g);
    measured.potential_force = free_part(dofs, state.force);
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
    measured.damper_force = -(alpha / hs) * w.mass.cwiseProduct(moved) - damping * moved;
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
  // The nodes that landed leave with the ground's restitution (ground_restitution.hpp); BDF2's
  // history then starts again, its velocity before the impact being no longer the motion's. The
  // energy the rebound gives back is the scheme's: backward Euler's step into the penalty took it.
  const double kinetic_before = ends ? kinetic_energy(model, state.v_half) : 0.0;
  const bool rebounded = rebound_landing_nodes(model, w.x_start, w.v_start, state);
  if (ends) {
    state.energy.numerical_dissipation -= kinetic_energy(model, state.v_half) - kinetic_before;
  }
  w.friction.finish_step(model, state);
  w.objects.finish_step(model, state);
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
