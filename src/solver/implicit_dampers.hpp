#pragma once
// The dampers in the implicit integrator's incremental potential (implicit_integrator.hpp): each
// bar's axial damper c along its direction at the step's start, a dissipation ½ (c/h) (e·Δu)²
// of the bar's relative move Δu over the step, whose Hessian is (c/h) e eᵀ on the bar's blocks.
// (The global damping, α m/h on the diagonal, is the integrator's own.)
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

}  // namespace dinam
