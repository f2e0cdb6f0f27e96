#pragma once
// The bars' axial dampers in the implicit step's incremental potential
// (solver/implicit_integrator.hpp), their force kind's ImplicitDamper (force_kind.hpp): each
// bar's damper c along its direction at the step's start, a dissipation ½ (c/h) (e·Δu)² of the
// bar's relative move Δu over the step, whose Hessian is (c/h) e eᵀ on the bar's blocks.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"
#include "dynamics/free_dofs.hpp"

namespace dinam {

struct Model;
struct State;

// The axial dampers' Hessian for a step of h from `x_start` (x_n), as triplets over the free
// degrees of freedom; broken bars and bars without damping give none.
void add_axial_damper_hessian(const Model& model, const State& state, const FreeDofs& dofs,
                              const std::vector<Vec3>& x_start, double h,
                              std::vector<Eigen::Triplet<double>>& triplets);

// What the dampers of bars that join a free node to a pinned one add at the free end when the
// pinned end moves over the step (a support that moves, `pin_motion`): the dissipation's cross
// term, (c/h) e eᵀ Δx_p, Δx_p the pinned end's move from `x_base` to where state.x has placed it
// at t_{n+1}; N over the free degrees of freedom, constant within the step. (The Hessian above
// leaves the pinned end out, as if it held still.)
// Added to `force` (of the free dofs' size).
void add_axial_damper_support_pull(const Model& model, const State& state, const FreeDofs& dofs,
                                   const std::vector<Vec3>& x_start,
                                   const std::vector<Vec3>& x_base, double h,
                                   Eigen::VectorXd& force);

}  // namespace dinam
