#pragma once
// Everything that changes during a run. The model it belongs to is passed beside it.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "dynamics/contact/object_contact_state.hpp"
#include "dynamics/work_split.hpp"

namespace dinam {

// Work done and energy lost since t = 0, J, by what is not a potential of the positions.
struct EnergyAccounts {
  double damping_work = 0.0;          // axial dampers and global viscous friction (≤ 0)
  double plastic_dissipation = 0.0;   // Σ yield × |Δ plastic set|, and torn springs (≥ 0)
  double friction_work = 0.0;         // tangential contact forces (≤ 0 over a slide)
  double contact_damping_work = 0.0;  // contact normal damping (≤ 0)
  double wind_work = 0.0;             // aerodynamic drag
  double field_work = 0.0;            // field forces other than gravity
  // What supports that move (pin_motion) did to the structure: −Σ F·v at the pinned nodes, F
  // the structure's force on its node there. Zero while every pin holds still.
  double support_work = 0.0;
  // What the implicit integrator's scheme took out (solver/implicit_energy.hpp); central
  // differences book none, their error staying in the total.
  double numerical_dissipation = 0.0;

  // Adds `fraction` of every work in `works` (the dissipation is booked elsewhere).
  void add_works(const EnergyAccounts& works, double fraction) {
    damping_work += fraction * works.damping_work;
    contact_damping_work += fraction * works.contact_damping_work;
    friction_work += fraction * works.friction_work;
    wind_work += fraction * works.wind_work;
    field_work += fraction * works.field_work;
    support_work += fraction * works.support_work;
  }
};

// The energy of the system at one whole step, and what has come in and gone out since t = 0.
// The balance `total` stays constant up to the integrator's error: potential and kinetic energy
// plus what the dissipative forces and the implicit scheme took, minus what driving forces gave.
struct EnergyReport {
  double time = 0.0;           // s
  double kinetic = 0.0;        // J, Σ ½ m |v_n|², v_n = ½ (v_{n−½} + v_{n+½})
  double axial = 0.0;          // J, elastic energy of the axial springs
  double bending = 0.0;        // J
  double torsion = 0.0;        // J
  double gravitational = 0.0;  // J, Σ −m g·x
  double contact = 0.0;        // J, elastic energy of the normal penalties (ground, objects)
  EnergyAccounts accounts;
  double total = 0.0;  // kinetic + elastic + gravitational + contact − works + dissipations
};

// The dissipative and driving forces by kind and the energy report, while the energy is tracked
// (the arrays are empty otherwise).
struct EnergyWorkspace {
  bool enabled = false;
  std::vector<Vec3> damping;          // (n_nodes) N
  std::vector<Vec3> contact_damping;  // (n_nodes) N
  std::vector<Vec3> friction;         // (n_nodes) N
  std::vector<Vec3> wind;             // (n_nodes) N
  std::vector<Vec3> field;            // (n_nodes) N
  std::vector<Vec3> v_whole;          // (n_nodes) m/s, ½ (v_{n−½} + v_{n+½}) of the last step
  // The work each spring's plastic flow dissipated in the last step, J, for the kinds that can
  // yield (empty for the others), booked in spring order after the step whatever the threads.
  std::vector<double> bar_flow;      // (n_bars)
  std::vector<double> bend_flow;     // (n_bends)
  std::vector<double> torsion_flow;  // (n_torsions)
  std::vector<double> clamp_flow;    // (n_clamps)
  EnergyReport last;                 // at the last step taken

  // The five per-kind force arrays, to clear or size them together.
  std::array<std::vector<Vec3>*, 5> force_parts() {
    return {&damping, &contact_damping, &friction, &wind, &field};
  }
};

// How the settling phase before t = 0 ended (solver/settle.hpp); `ran` is false without one.
struct SettleOutcome {
  bool ran = false;
  bool by_newton = false;  // Newton's method on the potential energy, else dynamic relaxation
  int newton_iterations = 0;
  // Why relaxation served where Newton's method was asked for; empty when it was not.
  std::string fallback;
  std::int64_t steps = 0;          // relaxation: steps taken until it converged, in all
  double step = 0.0;               // s, relaxation's step (the motion's, or with the implicit
                                   // integrator the automatic explicit one)
  std::int64_t viscous_steps = 0;  // of which overdamped, before kinetic damping
  std::int64_t max_steps = 0;      // relaxation: the most it could take (settle.duration)
  double residual = 0.0;  // largest out-of-balance force on a free node / that node's weight
  Index worst_node = -1;  // the node with that force
  int restarts = 0;       // kinetic-energy peaks, each a restart from rest
  bool stopped = false;   // relaxation ended early by its caller's test at a restart
};

// The wind's scratch (empty without wind): the wind at each node where it is turbulent, and the
// drag on each face and bar it blows on, before the nodes gather them.
struct WindWorkspace {
  std::vector<Vec3> node_wind;   // (n_nodes when turbulent) m/s, at t_n
  std::vector<Vec3> item_force;  // (n_wind_faces + n_wind_bars) N, on each of the item's nodes
};

// A plastic set to write once the threads have met.
struct PlasticSetUpdate {
  double* slot;
  double value;
};

// A bar held as a constraint, as its projection reads it (dynamics/bar_constraints.hpp): its
// nodes and what the step's length and its material make of it, in one record.
struct BarProjection {
  Index bar = 0;
  Index i = 0;
  Index j = 0;
  double wi = 0.0;  // 1/kg, its ends' inverse masses
  double wj = 0.0;
  double rest = 0.0;         // m
  double compliance = 0.0;   // α̃ = 1/(k h²), 1/kg; 0 for a bar that is no constraint
  double gamma = 0.0;        // c/(k h), its damper's share
  double denominator = 0.0;  // 1 / ((1 + γ)(w_i + w_j) + α̃), kg
};

// The state at step n: positions at t_n, the velocities as the stepper carries them.
struct State {
  double time = 0.0;      // s, t_n
  std::int64_t step = 0;  // n
  // s, the step being taken (set by the integrator); 0 while forces are found at rest
  // (compute_static_forces), where the contact dampers then act on the velocities alone.
  double dt = 0.0;
  std::vector<Vec3> x;  // (n_nodes) m, x_n
  // (n_nodes) m/s, the velocity the stepper carries with x_n, which the forces that depend on
  // velocity (the dampers, the wind, the contacts' dampers) read: leapfrog's v_{n−½} under central
  // differences, v_n under the implicit schemes (stepping/stepper.hpp).
  std::vector<Vec3> velocity;
  std::vector<Vec3> force;  // (n_nodes) N, scratch: the total force at t_n on each node
  // (n_nodes) scratch: x_{n+1} and v_{n+½} as a step writes them, swapped with x and velocity once
  // every thread has read the old ones (so the threads meet once a step, not twice).
  std::vector<Vec3> x_next;
  std::vector<Vec3> v_next;
  // (n_bars, or 0 unless the bars are constraints) N·s², scratch: the step's XPBD multiplier of
  // each bar (dynamics/bar_constraints.hpp), λ/h² its tension.
  std::vector<double> bar_lambda;
  // (n_bars, or 0 unless the bars are constraints) what each bar's projection reads, packed, for
  // the step length it was made for, in the order the sweeps take them (bar_constraints.cpp).
  std::vector<BarProjection> bar_projection;
  double bar_projection_step = 0.0;  // s, the step `bar_projection` was made for

  std::vector<double> bar_plastic_set;      // (n_bars) m
  std::vector<double> bend_plastic_set;     // (n_bends) rad
  std::vector<double> torsion_plastic_set;  // (n_torsions) rad
  std::vector<double> clamp_plastic_set;    // (n_clamps) rad
  // Tearing (empty unless the model can tear): 1 for what has broken, for good.
  std::vector<std::uint8_t> bar_broken;      // (n_bars)
  std::vector<std::uint8_t> bend_broken;     // (n_bends)
  std::vector<std::uint8_t> torsion_broken;  // (n_torsions)
  std::vector<std::uint8_t> clamp_broken;    // (n_clamps)
  std::vector<std::uint8_t> face_broken;     // (n_faces) faces with a broken edge
  std::vector<Index> broken_bars;            // in the order they broke
  // Ties (`attach`, dynamics/tie_springs.hpp): 1 for a broken one (empty unless some can break);
  // under `integrator: xpbd` each one's multiplier in the step (N·s²) and its last tension (N).
  std::vector<std::uint8_t> tie_broken;  // (n_ties)
  std::vector<double> tie_lambda;        // (n_ties)
  std::vector<double> tie_tension;       // (n_ties)

  // Ground contact history (empty without a ground): where each node's stick spring is anchored
  // on the plane, and whether it is sliding (kinetic friction) or sticking (static).
  std::vector<Vec3> contact_anchor;            // (n_nodes) m
  std::vector<std::uint8_t> contact_touching;  // (n_nodes) 1 while below the plane
  std::vector<std::uint8_t> contact_sliding;   // (n_nodes) 1 while sliding

  WindWorkspace wind;
  // Which thread owns which nodes and evaluates which springs, for the team size it was made for
  // (made at the first step that shares its work; work_split.hpp).
  WorkSplit work_split;
  // (n_threads) the new plastic sets of springs that two threads evaluate, put aside by the one
  // that keeps them until the other has read the old ones (spring_block.hpp); room for every
  // spring that is shared, so that no step allocates.
  std::vector<std::vector<PlasticSetUpdate>> plastic_set_updates;
  // Contact between objects (empty unless the model has it).
  ObjectContactWorkspace object_contact;
  EnergyAccounts energy;
  EnergyWorkspace energy_workspace;
  SettleOutcome settled;  // how the shape at t = 0 was reached
};

}  // namespace dinam
