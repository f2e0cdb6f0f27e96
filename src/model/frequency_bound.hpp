#pragma once
// Upper bounds of the model's highest natural frequency and damping rate at rest, without any
// eigen-solve: they set the stable time step.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

// Whether a bound counts the bars' own springs and dampers: as the model's integrator takes them
// (central differences' springs, `xpbd`'s constraints, which bound no step), held as constraints
// whatever the model's integrator (`dinam info` estimating an xpbd run from another's model), or
// as springs (the settling phase, which relaxes an xpbd model with its bars as springs).
enum class BarsIn { kTheModelsWay, kConstraints, kSprings };

// Whether the bars' springs are left out of a bound asked with `bars` of `model`.
bool bars_left_out(const Model& model, BarsIn bars);

// The bound's sums, which each kind of spring adds its terms to (ModelSpringKind::
// add_frequency_terms): the diagonal blocks (N/m) and the scaled couplings (1/s²).
struct GershgorinSums {
  std::vector<Mat3> diagonal;    // (n_nodes) Σ k g_i g_iᵀ, or an isotropic upper bound of it
  std::vector<double> coupling;  // (n_nodes) Σ k |g_i| |g_j| / √(m_i m_j) over free j ≠ i

  // Whether the bars' own springs are left out (bars_left_out): held as constraints
  // (`integrator: xpbd`), they bound no step.
  bool bars_held = false;

  explicit GershgorinSums(Index n) : diagonal(n, Mat3::Zero()), coupling(n, 0.0) {}

  // A spring k over `count` (≤ 4) nodes whose gradient blocks have norms at most `norms`. A
  // pinned node (inverse mass 0) neither couples nor is coupled to: its terms are exactly 0.
  void add(const Model& model, double k, const Index* nodes, const double* norms, int count);
};

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
double max_frequency_squared_bound(const Model& model, bool include_contact = true,
                                   BarsIn bars = BarsIn::kTheModelsWay);

// The bound's row of every node, 1/s²: `own` = λ_max(Σ k g_i g_iᵀ) / m_i and `coupling` = the
// sum over the other free nodes; both 0 for a pinned node. The bound is the largest own +
// coupling; a node's row says how fast the springs at that node alone let it vibrate, so the
// rows show which nodes limit the step (`dinam info`) and how much mass would free it
// (mass scaling).
struct NodeFrequencyRows {
  std::vector<double> own;       // (n_nodes)
  std::vector<double> coupling;  // (n_nodes)
};
NodeFrequencyRows node_frequency_rows(const Model& model, bool include_contact = true,
                                      BarsIn bars = BarsIn::kTheModelsWay);

// An upper bound of the damping rates, 1/s: λ_max(M⁻¹C) by the same Gershgorin argument as the
// frequency bound, over the global friction α, the axial dampers and the ground's normal damping.
// Without `include_contact`, the ground's damping is left out.
double max_damping_rate_bound(const Model& model, BarsIn bars = BarsIn::kTheModelsWay,
                              bool include_contact = true);

// The fraction of the critical step that `timestep: auto` uses, leaving room for the stiffening
// that large rotations and tension add beyond the rest-state bound.
inline constexpr double kAutoTimestepSafety = 0.8;

}  // namespace dinam
