#pragma once
// The bars as constraints (`integrator: xpbd`, the solver for stiff threads): the paper's rigid
// bars, compliant. A step is central differences' on every force but the bars' own axial springs
// and dampers, which carries the nodes to x̃_{n+1}; then each bar is drawn towards its rest length
// by XPBD (Macklin, Müller and Chentanez, "XPBD: position-based simulation of compliant
// constrained dynamics", 2016): C = |x_j − x_i| − L0 with compliance 1/k (k = E A / L0, the bar's
// own spring) and damping c (its damper), each bar's correction along its present direction
//   Δλ = −(C + α̃ λ + γ ∇C·(x − x_n)) / ((1 + γ)(w_i + w_j) + α̃),   α̃ = 1/(k h²), γ = c/(k h),
// λ the step's sum of them (λ/h² the bar's tension, N), over kConstraintSweeps Gauss–Seidel
// sweeps (kConstraintSweeps), forward then back. The velocities follow the positions: v_{n+½} =
// (x_{n+1} − x_n)/h.
//
// Why: a cloth's or a rope's threads barely stretch, and their stretch alone sets central
// differences' step (66 µs for cotton, 3 µs for a steel cable) while the motion one sees is the
// bending, shearing and swinging, a ten to a hundred times slower. Held as constraints, the bars
// no longer bound the step (model/frequency_bound.hpp leaves them out): the step is the softer
// springs' (bench/notes/stiff-threads.md). A few sweeps leave the bars a little more stretchy
// than the material (their error is a share of what one step's loads stretch them by), which a
// flag or a rope does not show.
//
// Serial, on one thread, in bar order: the same bits whatever the thread count. Broken bars
// are skipped, as are bars of no stiffness (a sheet's triangles' shared sides).

namespace dinam {

struct Model;
struct State;

// The longest step at which the sweeps hold the bars (s): the one in which gravity and the fields
// would move a free node by kLoadStretchShare of the median bar, a h² = share × L, beyond which a
// few sweeps leave the bars visibly stretched (the paper's flag at steps of 4 ms, 0.7 mm a step:
// its mean 5.9 cm from central differences'; at 2 ms, 2.5 cm). The wind is left out: a flag in
// it streams out, its drag borne by the threads' tension, and the windy flag's 0.6 ms steps
// hold it within 1.1 cm. Infinite where no load acts.
inline constexpr double kLoadStretchShare = 5e-4;
double bar_constraint_step_cap(const Model& model);

// One sweep of the bars' projection (ConstraintHold::project, spring_kind.hpp): each bar in turn,
// in bar order on even sweeps and backwards on odd ones, its multiplier in state.bar_lambda.
void project_bars(const Model& model, double h, int sweep, State& state);
// After the last sweep (ConstraintHold::finish): a bar held at its yield force keeps what it is
// stretched by beyond its elastic share, C + α̃ λ, as its new plastic set.
void flow_bars(const Model& model, double h, State& state);

}  // namespace dinam
