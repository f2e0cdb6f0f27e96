#pragma once
// The dampers in the implicit integrator's incremental potential (implicit_integrator.hpp): each
// bar's axial damper c along its direction at the step's start, a dissipation ½ (c/h) (e·Δu)²
// of the bar's relative move Δu over the step, whose Hessian is (c/h) e eᵀ on the bar's blocks.
// (The global damping, α m/h on the diagonal, is the integrator's own.)
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;
struct State;
struct FreeDofs;

// The axial dampers' Hessian for a step of h from `x_start` (x_n), as triplets over the free
// degrees of freedom; broken bars and bars without damping give none.
void add_damper_hessian(const Model& model, const State& state, const FreeDofs& dofs,
                        const std::vector<Vec3>& x_start, double h,
                        std::vector<Eigen::Triplet<double>>& triplets);

// What the dampers of bars that join a free node to a pinned one add at the free end when the
// pinned end moves over the step (a support that moves, `pin_motion`): the dissipation's cross
// term, (c/h) e eᵀ Δx_p, Δx_p the pinned end's move from `x_base` to where state.x has placed it
// at t_{n+1}; N over the free degrees of freedom, constant within the step. (The Hessian above
// leaves the pinned end out, as if it held still.)
// Into `force`, its storage reused.
void pinned_damper_forces(const Model& model, const State& state, const FreeDofs& dofs,
                          const std::vector<Vec3>& x_start, const std::vector<Vec3>& x_base,
                          double h, Eigen::VectorXd& force);

}  // namespace dinam
