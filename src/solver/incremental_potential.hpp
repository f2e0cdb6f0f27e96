#pragma once
// The incremental potential a step of the implicit integrator minimises (implicit_integrator.hpp),
// over the free nodes:
//   E(x) = Σ m/(2h²)|x − x̂|² + α m/(2h)|x − x_b|² + ½ (x − x_b)ᵀ D (x − x_b) − f_pᵀ(x − x_b)
//          + V(x) + the friction springs' and the contact's potentials,
// with h the step solved for, D the dampers' Hessian at x_n and f_p the dampers' pull from
// supports that move. Its gradient and energy evaluate the model's forces at state.x.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"
#include "dynamics/force_switches.hpp"

namespace dinam {

struct FreeDofs;
struct Model;
struct State;
class ImplicitFriction;
class ImplicitObjectContact;

// The forces that derive from V: springs, gravity and the ground's normal penalty
// (force_kinds.hpp), found by compute_potential_forces, which reads no velocity and no friction
// anchor. Contact between objects is ImplicitObjectContact's, outside the switches.
ForceSwitches potential_switches();

struct IncrementalPotential {
  using Vector = Eigen::VectorXd;

  const FreeDofs& dofs;
  const Vector& mass;                // (dofs)
  const std::vector<Vec3>& x_start;  // x_n, for the springs' flow from their plastic sets
  ImplicitFriction& friction;
  ImplicitObjectContact& objects;
  const Model* model = nullptr;  // the step's (set with the step)
  State* state = nullptr;
  double hs = 0.0;              // s, the step solved for (2h/3 for BDF2's two-step steps)
  double alpha = 0.0;           // 1/s, the global damping
  Vector predicted = Vector();  // x̂
  Vector start = Vector();      // x_b
  const Eigen::SparseMatrix<double>* damping = nullptr;  // D
  Vector pinned_damping = Vector();                      // f_p
  Vector inertia = Vector();  // M/h² + α M/h, the Hessian's diagonal beside the stiffness
  ForceSwitches switches = potential_switches();
  // The free part of x, x − x_b, x − x̂, D (x − x_b) and the forces, kept from call to call so
  // that neither allocates.
  mutable Vector x = Vector(), moved = Vector(), off = Vector(), damped = Vector(),
                 forces = Vector();

  // g = M(x − x̂)/h² − F(x) + ∇hD; leaves the potential's forces at x in state.force.
  void gradient(Vector& g) const;
  double energy() const;
};

}  // namespace dinam
