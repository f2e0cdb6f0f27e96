#pragma once
// The memory Newton's method holds beside the state, for the memory estimate
// (estimate/memory_estimate.hpp): an implicit run's Hessian and its Cholesky factor grow faster
// than the model (a cloth of 40 000 nodes: 0.8 GB, where its explicit run holds 116 MB), and an
// estimate without them let a run pass that the machine could not hold.
#include <cstdint>

namespace dinam {

struct Model;
struct HessianFactorSize;

// Newton's method on the model's stiffness (the settle, an implicit step): the chunk of element
// matrices the assembly keeps for each spring kind (dynamics/stiffness.hpp), the
// Hessian twice (the assembly's and the matrix factorised, with the inertia, the dampers and the
// friction added), the solver's copy of its pattern, and the factor, `factor` the factor's size.
std::uint64_t newton_bytes(const Model& model, const HessianFactorSize& factor);

// What the implicit integrator holds at its peak: Newton's, its dampers' matrix, and its vectors.
std::uint64_t implicit_integrator_bytes(const Model& model);

}  // namespace dinam
