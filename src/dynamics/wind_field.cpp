#include "dynamics/wind_field.hpp"

#include <cmath>
#include <numbers>

#include "core/fast_sine.hpp"
#include "core/geometry.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// a = A / √(K/2): the amplitude of each wave for an RMS of A per component.
double wave_amplitude(const WindDesc& wind) {
  return wind.turbulence / std::sqrt(0.5 * kTurbulenceWaves);
}

}  // namespace

Vec3 uniform_wind_velocity(const WindDesc& wind, double t) {
  Vec3 velocity = wind.velocity;
  const double mean_speed = wind.velocity.norm();
  if (wind.gust_amplitude != 0.0 && mean_speed > 0.0) {
    velocity += (wind.gust_amplitude * std::sin(2.0 * std::numbers::pi * t / wind.gust_period) /
                 mean_speed) *
                wind.velocity;
  }
  return velocity;
}

TurbulencePhases turbulence_phases(const WindLoad& wind, double t) {
  TurbulencePhases phases{};
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const TurbulenceWave& wave = wind.waves[i];
    phases[i] = wave.phase + (wave.drift - dot3(wave.wavenumber, wind.field.velocity)) * t;
  }
  return phases;
}

Vec3 wind_at(const WindLoad& wind, const TurbulencePhases& phases, const Vec3& uniform,
             const Vec3& x) {
  if (wind.field.turbulence == 0.0) {
    return uniform;
  }
  double u = 0.0;
  double v = 0.0;
  double w = 0.0;
  wind_at_points(wind, phases, uniform, &x.x(), &x.y(), &x.z(), 1, &u, &v, &w);
  return {u, v, w};
}

// sin(k·x + phase) summed over a component's waves; the place's part of each phase is at most
// |k| |x|, a few hundred radians, where fast_sin keeps its accuracy.
void wind_at_points(const WindLoad& wind, const TurbulencePhases& phases, const Vec3& uniform,
                    const double* x, const double* y, const double* z, Index count, double* u,
                    double* v, double* w) {
  // The waves' constants as plain arrays, so that the loop below keeps them in registers.
  constexpr int kWaves = 3 * kTurbulenceWaves;
  double kx[kWaves];
  double ky[kWaves];
  double kz[kWaves];
  for (int i = 0; i < kWaves; ++i) {
    kx[i] = wind.waves[static_cast<std::size_t>(i)].wavenumber.x();
    ky[i] = wind.waves[static_cast<std::size_t>(i)].wavenumber.y();
    kz[i] = wind.waves[static_cast<std::size_t>(i)].wavenumber.z();
  }
  const double amplitude = wave_amplitude(wind.field);
  double* out[3] = {u, v, w};
  for (int c = 0; c < 3; ++c) {
    double* component = out[c];
    const double base = uniform[c];
#pragma omp simd
    for (Index p = 0; p < count; ++p) {
      double sum = 0.0;
      for (int k = 0; k < kTurbulenceWaves; ++k) {
        const int i = c * kTurbulenceWaves + k;
        sum += fast_sin(kx[i] * x[p] + ky[i] * y[p] + kz[i] * z[p] +
                        phases[static_cast<std::size_t>(i)]);
      }
      component[p] = base + amplitude * sum;
    }
  }
}

Vec3 wind_velocity(const WindDesc& wind, const Vec3& x, double t) {
  WindLoad load;
  load.field = wind;
  if (wind.turbulence != 0.0) {
    load.waves = make_turbulence_waves(wind.seed, wind.turbulence_scale);
  }
  return wind_at(load, turbulence_phases(load, t), uniform_wind_velocity(wind, t), x);
}

}  // namespace dinam
