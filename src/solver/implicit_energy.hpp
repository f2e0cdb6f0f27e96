#pragma once
// The energy ledger of the implicit integrator (`--energy`): central differences' accounts
// (dynamics/state.hpp), kept over steps of backward Euler or BDF2, and beside them the energy the
// scheme itself takes out, booked as numerical dissipation.
//
// A step of either scheme is backward Euler's of h_s from a base (x_b, v_b) (implicit_integrator
// .hpp; x_b = x_n, v_b = v_n, h_s = h for backward Euler):
//   M (v_{n+1} − v_b) = h_s (F_P(x_{n+1}) + F_d + F_e + r),   x_{n+1} − x_b = h_s v_{n+1},
// with F_P = −∇P the forces of the step's potential P (the springs with their flow's work,
// gravity, the ground's and the objects' penalties, the friction springs), F_d the dampers' at
// v_{n+1}, F_e the fields' and the wind's, and r what Newton's method leaves out of balance.
// Dotted with v_{n+1}:
//   K_{n+1} − K_b + ½ |v_{n+1} − v_b|²_M = (F_P + F_d + F_e + r)·(x_{n+1} − x_b).
// The works are booked along the step's own move Δx = x_{n+1} − x_n: F_d·Δx, F_e·Δx, and the
// friction springs' loss of energy. What the scheme took out is then
//   N = K_n − K_b + ½ |v_{n+1} − v_b|²_M + P(x_n) − P(x_{n+1}) − F_P·(x_{n+1} − x_b)
//       + (F_d + F_e)·(x_b − x_n),
// and the balance E_{n+1} + N = E_n + W holds up to r·(x_{n+1} − x_b) alone: the total stays
// constant to what the convergence test lets Newton leave, and a term booked wrong shows in it.
// For backward Euler N = ½ |Δv|²_M + P(x_n) − P(x_{n+1}) − ∇P(x_{n+1})·(x_n − x_{n+1}), the
// kinetic energy of the velocity's jump plus the Bregman divergence of P, never negative where P
// is convex: the scheme only ever takes energy out. BDF2's N has no sign from step to step.
// Supports that move (pin_motion) are placed at t_{n+1} before the step, so P's change holds
// their move too: the support's work S = F_P,pin(x_{n+1})·(x_{n,pin} − x_{n+1,pin}), the same
// quadrature, is booked as support work, and N takes the dot product over the pinned nodes as
// well as the free ones (backward Euler's N is then still the whole Bregman divergence of P).
#include <Eigen/Dense>
#include <vector>

#include "dynamics/state.hpp"

namespace dinam {

// One step's ends, over the free degrees of freedom (pinned nodes neither move by the step's
// forces nor count in the kinetic energy).
struct ImplicitStepEnds {
  Eigen::VectorXd mass;              // kg
  Eigen::VectorXd x_start, v_start;  // x_n, v_n
  Eigen::VectorXd x_base, v_base;    // x_b, v_b
  Eigen::VectorXd x_end, v_end;      // x_{n+1}, v_{n+1}
  Eigen::VectorXd potential_force;   // N, F_P at x_{n+1}
  Eigen::VectorXd damper_force;      // N, F_d at v_{n+1}
  // N, each load's forces over the step (the fields', the wind's), and the account of the
  // energy ledger its work is booked on.
  struct Load {
    double EnergyAccounts::*work;
    Eigen::VectorXd force;
  };
  std::vector<Load> loads;
  double potential_start = 0.0;  // J, P(x_n), the step's friction springs included
  double potential_end = 0.0;    // J, P(x_{n+1})
  double friction_start = 0.0;   // J, the friction springs' share of P(x_n)
  double friction_end = 0.0;     // J, and of P(x_{n+1})
  double support_work = 0.0;     // J, S: the moving supports' (0 where none moves)
};

// The works and the numerical dissipation of the step (the plastic flow's is booked with the new
// plastic sets, the tearing's where bars break, as in central differences).
EnergyAccounts implicit_step_accounts(const ImplicitStepEnds& ends);

// Σ ½ m v² over the free degrees of freedom, J.
double free_kinetic_energy(const Eigen::VectorXd& mass, const Eigen::VectorXd& v);

}  // namespace dinam
