#pragma once
// Backward Euler beside central differences (`integrator: implicit`): each step of h minimises the
// incremental potential
//   E(x) = Σ m/(2h²) |x − x̂|² + V(x) + h D((x − x_n)/h),   x̂ = x_n + h v_n + h² M⁻¹ F_e,
// where V is the potential of the springs, gravity, the ground's normal penalty (potential.hpp)
// and the ground's friction (its stick springs, capped at μ times the normal force at x_n:
// ground_friction_implicit.hpp), and contact between objects' penalty and friction (likewise:
// object_contact_implicit.hpp), D the dampers' dissipation (the bars' axial dampers along their
// directions at x_n, and the global damping), and F_e the forces outside the potential: the
// fields at t_{n+1} (they depend on the time alone) and the wind at (x_n, v_n). The ground's and
// the contact's dampers are left out: backward Euler's long step into a penalty ends an impact
// at rest, whatever their damping_ratio says; so a node that lands on the ground within a step
// leaves it with the damper's restitution (ground_restitution.hpp), while contact between
// objects' short steps bounce by themselves. The minimum is found by Newton's method in a trust
// region on E (implicit_newton.hpp): each Newton step by truncated conjugate gradients with the
// Hessian's products taken from differences of the gradient, preconditioned with a factorised
// sparse Hessian (stiffness_matrix.hpp) that is kept over iterations and steps until the solve
// stops converging in a few iterations; then v_{n+1} = (x_{n+1} − x_n)/h. With `integrator:
// implicit_bdf2` (ImplicitScheme:: kBdf2) a step of h after one of the same h is BDF2's, which is
// backward Euler's of 2h/3 from x_b = (4 x_n − x_{n−1})/3 and v_b = (4 v_n − v_{n−1})/3 in the
// place of x_n and v_n (the first step, and the first after a change of h, is backward Euler's).
// Either is L-stable: a step is never limited by the stiffest bar. It is split in halves where
// Newton does not converge or where its local error, h²/2 |a_{n+1} − a_n| at some node, passes
// kImplicitErrorShare of the median bar (but for a step in which a node meets or leaves the
// ground), and the halving is kept for the steps that follow until a few of them have gone
// through: a folding structure that needed it for one step needs it for the next, and a step
// tried whole again only to fail costs a whole minimisation.
//
// Springs that yield: the plastic sets are held at the step's start while Newton minimises the
// stored energy plus the work of the flow from them (SpringEnergy::kWithFlow, whose gradient is
// the flattened force: a return mapping at every iterate), and kept at the step's end.
// Bars past their breaking limit at x_n break at the step's start, as in central differences.
// Contact between objects and within one: its penalty a potential and its friction lagged
// (object_contact_implicit.hpp), the step split where a node of it would pass its speed envelope.
// The state's velocities are v_n, not leapfrog's v_{n−½}.
#include <memory>
#include <optional>

#include "dynamics/integrator.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

// The largest position error a step may make at a node, as a share of the median bar length.
inline constexpr double kImplicitErrorShare = 0.05;

struct ImplicitStats {
  std::int64_t steps = 0;             // steps taken, halves counted
  std::int64_t iterations = 0;        // Newton iterations, in all
  std::int64_t solve_iterations = 0;  // of the Newton steps' conjugate gradients, in all
  std::int64_t factorizations = 0;    // Hessians assembled and factorised
  std::int64_t splits = 0;            // times the sub-step was halved
};

// The implicit step resolves no contact oscillation (its steps are far longer than one): the
// ground's automatic penalty is softened to ω_c h = kImplicitGroundFrequency for the run's longest
// step h, stiff enough that a landing node sinks about a hundredth of the way it travels in a step
// (backward Euler's step into the spring stops it at 1/(1 + ω_c²h²) of it) and g/ω_c² under its
// weight (15 µm at 4 steps a frame of 20 fps), and soft enough that Newton's method does not stall
// on the ground's kink (bench_implicit, the Wuson's first 0.5 s: 6.3 s at ω_c h = 10, 11 s at 20,
// 34 s at central differences' ω_c, where ω_c h is about 200).
inline constexpr double kImplicitGroundFrequency = 10.0;

// How each step's incremental potential is minimised: Newton's method in a trust region (the
// integrator's), or quasi-Newton about projective dynamics' constant matrix (quasi_newton.hpp),
// which the comparison of the solvers for stiff threads measures (bench/notes/stiff-threads.md).
enum class ImplicitMinimiser { kNewton, kQuasiNewton };

struct ImplicitOptions {
  // s, the run's longest step, for the ground's softening; empty: the model's ground as it is.
  std::optional<double> longest_step;
  ImplicitMinimiser minimiser = ImplicitMinimiser::kNewton;
};

class ImplicitIntegrator {
 public:
  // Whether it steps its own copy of `model` (the ground softened) rather than the model itself.
  static bool copies_model(const Model& model);

  // Steps `model`, or its copy with the ground softened for `options.longest_step`.
  explicit ImplicitIntegrator(const Model& model, const ImplicitOptions& options = {});
  ~ImplicitIntegrator();
  ImplicitIntegrator(const ImplicitIntegrator&) = delete;
  ImplicitIntegrator& operator=(const ImplicitIntegrator&) = delete;

  // Advances `state` (positions x_n, velocities v_n in state.velocity, time t_n) by `steps` steps
  // of h, each split as often as it needs. Throws RuntimeError naming the time where even a step
  // of h/2¹⁰ does not converge.
  void advance(State& state, double h, std::int64_t steps);

  // While the energy is tracked (State::energy_workspace), its report at the state as it is, the
  // start of the run; each step books its own (implicit_energy.hpp).
  void report_energy(State& state);

  const ImplicitStats& stats() const { return stats_; }
  // The model as this integrator steps it (its ground softened).
  const Model& model() const { return model_; }

 private:
  struct Workspace;
  // One step of h; false (and `state` as it was) where Newton did not converge or, with
  // `check_error`, the local error is too large.
  bool try_step(State& state, double h, bool check_error);
  // One step of h in sub-steps of h/2^level_, the level carried from sub-step to sub-step and
  // from step to step: one deeper where a sub-step fails, one shallower after a few succeed.
  void step_adaptively(State& state, double h);

  std::unique_ptr<const Model> softened_;  // the model with its ground softened, where it is
  const Model& model_;
  std::unique_ptr<Workspace> work_;
  ImplicitStats stats_;
  // The splitting a step of `split_of_h_` needs now: its sub-steps are h/2^level_, and
  // taken_at_level_ of them have been taken since the level last changed.
  double split_of_h_ = 0.0;
  int level_ = 0;
  int taken_at_level_ = 0;
};

}  // namespace dinam
