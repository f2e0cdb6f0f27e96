#pragma once
// An upper bound of the model's highest natural frequency at rest, without any eigen-solve.
namespace dinam {

struct Model;

// Upper bound of ω_max², rad²/s², by the block Gershgorin theorem on D = M^{-½} K M^{-½} over
// the free nodes. Every spring's stiffness is a sum of rank-one terms k g gᵀ, g the gradient of
// its measure (length, angle, twist) with one 3-vector block g_i per node; the block D_ij has norm
// at most Σ k |g_i| |g_j| / √(m_i m_j), and every eigenvalue lies within Σ_j ‖D_ij‖ of an
// eigenvalue of some diagonal block, so
//   ω_max² ≤ max over free i of  λ_max(Σ k g_i g_iᵀ) / m_i + Σ_{j ≠ i, free} k |g_i| |g_j| / √(m_i
//   m_j).
// Bars use their exact direction (g = ±n); bending and torsion springs use bounds of |g| from
// the rest geometry; ground contact adds its penalty stiffness to every node's diagonal block.
// It is exact for one mass on a spring and for the top mode of a uniform chain. Stiffening by
// tension and large rotations is not included: the automatic step keeps a margin for it.
double max_frequency_squared_bound(const Model& model, bool include_contact = true);

}  // namespace dinam
