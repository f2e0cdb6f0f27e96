#pragma once
// The central-difference method is stable only while Δt < 2 / ω_max, ω_max the highest natural
// frequency of the model. We bound ω_max from above without any eigen-solve (below), so the
// step we call critical is safe.
#include <optional>

#include "core/error.hpp"

namespace dinam {

struct Model;

// An upper bound of ω_max², rad²/s², by the block Gershgorin theorem on D = M^{-½} K M^{-½}
// over the free nodes, K the axial stiffness at rest (a bar b between i and j adds k n nᵀ to
// the blocks ii and jj and −k n nᵀ to ij and ji). Every eigenvalue of D lies within
// Σ_j ‖D_ij‖ of an eigenvalue of some diagonal block, so
//   ω_max² ≤ max over free nodes i of  λ_max(Σ_b k_b n_b n_bᵀ) / m_i + Σ_{b to free j} k_b / √(m_i
//   m_j).
// It is exact for one mass on a spring and for the highest mode of a uniform chain; pinned
// neighbours stiffen the diagonal block but add no coupling, and pinned nodes themselves do not
// move and are left out.
double max_frequency_squared_bound(const Model& model);

// 2 / ω_max from the bound above, s; infinite when nothing can vibrate.
double critical_timestep(const Model& model);

struct TimeStep {
  double dt = 0.0;          // s, the step in use
  int steps_per_frame = 1;  // frame interval / dt, a whole number
  double critical = 0.0;    // s, the stability limit
  bool automatic = false;
};

// The fraction of the critical step that `timestep: auto` uses, leaving room for the stiffening
// that large rotations and tension add beyond the rest-state bound.
inline constexpr double kAutoTimestepSafety = 0.8;

// Chooses the step: `auto` (empty `requested`) takes kAutoTimestepSafety × critical; an explicit
// step above the critical one is refused with both numbers, naming `where`. Either way the step
// is shortened, if needed, so that a whole number of steps fills each frame.
TimeStep choose_timestep(const Model& model, std::optional<double> requested, double fps,
                         const FileLoc& where);

}  // namespace dinam
