#pragma once
// The wind velocity field: the mean, gusts along the mean direction (a sine of the gust period),
// and smooth seeded turbulence: kTurbulenceWaves travelling sine waves per component
// (model/wind_load.hpp), of wavelengths around the turbulence scale, carried along by the mean
// wind and drifting slowly in time:
//   u_c(x, t) = w̄_c + gust(t) ŵ_c + a Σ_k sin(k_ck·(x − w̄ t) + φ_ck + ω_ck t),  a = A / √(K/2),
// so that the RMS of each component is the amplitude A asked for (a sum of K unit sines of
// independent phases has mean square K/2).
#include <array>

#include "core/types.hpp"
#include "model/wind_load.hpp"

namespace dinam {

struct WindDesc;
struct WindLoad;

// The mean wind with its gust at time t, the same everywhere.
Vec3 uniform_wind_velocity(const WindDesc& wind, double t);

// The part of each wave's phase that does not depend on the place: φ + (ω − k·w̄) t.
using TurbulencePhases = std::array<double, 3 * kTurbulenceWaves>;
TurbulencePhases turbulence_phases(const WindLoad& wind, double t);

// The wind at x: `uniform` (uniform_wind_velocity at the phases' time) plus the turbulence (by
// wind_at_points, for one point).
Vec3 wind_at(const WindLoad& wind, const TurbulencePhases& phases, const Vec3& uniform,
             const Vec3& x);

// The wind at `count` points given by their coordinates (x[k], y[k], z[k]), into u, v, w (its
// components); one point per SIMD lane, twelve branch-free sines each (core/fast_sine.hpp).
void wind_at_points(const WindLoad& wind, const TurbulencePhases& phases, const Vec3& uniform,
                    const double* x, const double* y, const double* z, Index count, double* u,
                    double* v, double* w);

// The wind at one point and time, for a wind description alone (its waves made on each call).
Vec3 wind_velocity(const WindDesc& wind, const Vec3& x, double t);

}  // namespace dinam
