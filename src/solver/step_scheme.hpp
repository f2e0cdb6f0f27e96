#pragma once
// The time scheme of one implicit step (implicit_integrator.hpp): backward Euler, or BDF2 after a
// step of the same length, as backward Euler's step of 2h/3 from a base made of the last two
// states. What the step is solved from and towards (the base, the prediction x̂), when it is good
// enough (the local error), and the history the next step is based on. The step's problem, made of
// each force kind's terms, is step_problem.hpp's; its minimisation, step_minimiser.hpp's.
#include <vector>

#include "core/types.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;

struct StepScheme {
  // The step being tried: its length h, the length hs the minimisation takes (2h/3 for BDF2's
  // two-step steps) and the time it ends at.
  double h = 0.0;
  double hs = 0.0;
  double t_next = 0.0;
  std::vector<Vec3> x_start, v_start;  // (n_nodes) x_n, v_n
  // (n_nodes) the state the step is solved from: (x_n, v_n) for backward Euler; for BDF2,
  // (4 x_n − x_{n−1})/3 and (4 v_n − v_{n−1})/3, with 2h/3 in the place of h.
  std::vector<Vec3> x_base, v_base;
  // BDF2's history: x_{n−1} and v_{n−1}, from the last step taken, of `before_h` (0: none).
  std::vector<Vec3> x_before, v_before;
  double before_h = 0.0;
  // (n_nodes) this step's accelerations, while it is judged, and the last step's.
  std::vector<Vec3> accel, accel_before;
  bool have_accel = false;

  // The state the step is solved from. BDF2 on M v' = F, x' = v: (3 y_{n+1} − 4 y_n + y_{n−1}) /
  // 2h = y'_{n+1} for y = x and v, which is backward Euler's step of 2h/3 from the base y_b =
  // (4 y_n − y_{n−1})/3. It needs the step before to have been as long as this one; the first
  // step, and one after a split, is backward Euler's.
  void set_base(const Model& model, const State& state, double step);

  // x̂ = x_b + h v_b + h² M⁻¹ F_e (h: the step solved for, F_e the loads), into `predicted`;
  // driven pins go to their places at t_{n+1}.
  void predict(const Model& model, const std::vector<Vec3>& loads, std::vector<Vec3>& predicted,
               State& state) const;

  // The state as it was before the step was tried.
  void restore(State& state) const;

  // v_{n+1} = (x_{n+1} − x_b)/h; the local error h²/2 |a_{n+1} − a_n|, a_n = (v_{n+1} − v_n)/h
  // over the whole step: false (to be split) where, with `check_error`, it passes `limit`
  // (m). A step in which contact began or ended (`contact_changed`) has a jump in acceleration that
  // no shorter step would smooth (an impact ends within it): it is not judged, nor is the next
  // against it.
  bool accept(const Model& model, State& state, bool check_error, bool contact_changed,
              double limit);

  // What the next step is judged and based on: this step's accelerations, and BDF2's history,
  // which starts again after a rebound (the velocity before the impact is no longer the
  // motion's). The state moves on to t_{n+1}.
  void keep_history(const Model& model, State& state, bool contact_changed, bool rebounded);
};

}  // namespace dinam
