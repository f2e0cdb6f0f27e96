#pragma once
// The problem one implicit step minimises (implicit_integrator.hpp), made of each force kind's
// terms as its descriptor says how the step takes it (force_kind.hpp, ImplicitTreatment): the
// potential's kinds (the springs, gravity, the ground's penalty) at every iterate, the loads at the
// step's start or end, the dampers' dissipation, the ground's friction and the contact between
// objects beside them; the tears at its start, the rebounds and the new plastic sets at its end,
// and its ends for the energy ledger. The time scheme it is solved over is step_scheme.hpp's.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/types.hpp"
#include "dynamics/contact/ground_friction_implicit.hpp"
#include "dynamics/contact/object_contact_implicit.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/free_dofs.hpp"
#include "dynamics/state.hpp"
#include "solver/implicit_energy.hpp"
#include "solver/incremental_potential.hpp"
#include "solver/triplet_matrix.hpp"

namespace dinam {

struct Model;
struct StepScheme;

struct StepProblem {
  // Over `model`'s free nodes; the potential's x_n is `scheme`'s, which must outlive it.
  StepProblem(const Model& model, const StepScheme& scheme);

  FreeDofs dofs;
  Eigen::VectorXd mass;         // (dofs)
  double envelope = 0.0;        // m, the most a node of contact between objects may move in a step
  bool any_yield = false;       // some spring can flow
  std::vector<Vec3> loads;      // (n_nodes) N, F_e: the forces outside the potential
  std::vector<Vec3> predicted;  // (n_nodes) m, x̂
  // The parts of `loads`, load by load in the order of kForceKinds (empty for the other kinds),
  // for the energy ledger.
  std::array<std::vector<Vec3>, kForceKinds.size()> load_forces;
  ImplicitFriction friction;
  ImplicitObjectContact objects;  // contact between objects and within one
  TripletMatrix dampers;          // D, the dampers' Hessian
  IncrementalPotential potential;
  bool contact_changed = false;  // a node met or left the ground, or a pair touched or parted
  bool rebounded = false;        // a node or a pair of the contact rebounded

  // 1. Bars strained past their breaking limit at x_n break, with what stands on them, as at the
  // start of a step of central differences (serially, so the same bars on any thread count; a
  // step tried again from the same x_n breaks nothing more).
  void break_bars(const Model& model, State& state) const;

  // 2. The forces outside the potential, kind by kind, each taken as a load: one of the time
  // alone (the fields) at t_{n+1}, as the scheme takes every force (taken at t_n they lagged a
  // ramped load by a whole step); one that depends on the motion (the wind) at (x_n, v_n). While
  // the energy is tracked each one's own forces are kept for its work.
  void take_loads(const Model& model, State& state, double t_next);

  // 3. The friction springs of the nodes on the ground, and the contact between objects, at x_n;
  // and while the energy is tracked, P at x_n (the springs, gravity and the ground's penalty, as
  // the step holds them) for the ledger, before the driven pins move.
  void start_contact(const Model& model, State& state, const StepScheme& scheme);

  // 4. The incremental potential of this step, about x̂ (`predicted`): each damper kind's
  // dissipation (its ImplicitDamper: the bars' along their directions at x_n, the global
  // damping's α m / h on the diagonal) and its pull from supports that move, their ends placed
  // at t_{n+1}.
  void set_potential(const Model& model, State& state, const StepScheme& scheme);

  // Whether positions `x` carry a node of the contact between objects past the speed envelope
  // (object_contact_implicit.hpp).
  bool past_envelope(const Model& model, const std::vector<Vec3>& x);

  // 5. Where the minimisation starts: x̂, or after a step that ended with a rebound, x̂ less the
  // rebound's velocities (x̂ + h (v_unbounced − v_n)) where its energy is lower. A node kicked
  // alone out of a stiff piece (ground_restitution.hpp) has an x̂ a rebound's h v away from its
  // neighbours, across bars a fraction of that long: its bars' energy there dwarfs the
  // inertia's, and Newton's method, in a trust region over a landscape far from quadratic,
  // crawled back (25 iterations a step, split after split, for a letter of assimp's collada.ogex
  // landing flat; 4 times the run). x̂ is still the step's inertia target, so the step solves the
  // same equations, and a loose node, whose x̂ is lower, still starts there and bounces.
  void place_start(State& state, const StepScheme& scheme);

  // 6. The step's ends for the energy ledger (implicit_energy.hpp), while it is kept: P, with the
  // friction springs the step ended with, at x_{n+1} and at x_n (start_contact's share and the
  // friction's, from x_n kept: the state stays at x_{n+1}), and its forces at x_{n+1}. Null
  // while the energy is not tracked.
  const ImplicitStepEnds* measure_ends(const Model& model, State& state, const StepScheme& scheme);

  // 7. Whether contact began or ended within the step: a node met or left the ground, or a pair
  // of primitives touched or parted (contact_changed).
  bool find_contact_change(const Model& model, State& state, const std::vector<Vec3>& x_start);

  // 8. The step kept: its works booked; the nodes that landed leave with the ground's
  // restitution (ground_restitution.hpp), and the pairs of primitives that met with the
  // contact's (object_contact_implicit.hpp). The energy the rebound gives back is the scheme's:
  // backward Euler's step into the penalty took it. The springs that flowed keep their new
  // plastic sets (the return mapping at x_{n+1}).
  void book_and_rebound(const Model& model, State& state, const StepScheme& scheme,
                        const ImplicitStepEnds* ends);

 private:
  DofTriplets damper_triplets_;
  // P at x_n (start_contact) and the step's ends (measure_ends), while the energy is tracked.
  double potential_at_start_ = 0.0;
  ImplicitStepEnds step_ends_;
  Eigen::VectorXd gradient_;  // scratch, where the ends' forces are found
  // The last step's velocities before its rebounds, and the start they would give (place_start).
  std::vector<Vec3> v_unbounced_, unbounced_start_;
};

}  // namespace dinam
