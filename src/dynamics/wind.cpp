#include "dynamics/wind.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "model/model.hpp"

namespace dinam {
namespace {

constexpr int kTurbulenceWaves = 4;  // per component

struct TurbulenceWave {
  Vec3 wavenumber;  // rad/m
  double phase;     // rad
};

// The waves of a seed, made once per seed: the noise must be the same at every call.
const std::vector<TurbulenceWave>& turbulence_waves(std::uint32_t seed, double scale) {
  thread_local std::uint32_t cached_seed = 0;
  thread_local double cached_scale = 0.0;
  thread_local std::vector<TurbulenceWave> waves;
  if (waves.empty() || cached_seed != seed || cached_scale != scale) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> spread(0.5, 1.5);
    waves.clear();
    for (int k = 0; k < 3 * kTurbulenceWaves; ++k) {
      Vec3 direction(unit(rng), unit(rng), unit(rng));
      direction.normalize();
      const double magnitude = 2.0 * std::numbers::pi / scale * spread(rng);
      waves.push_back({magnitude * direction, std::numbers::pi * unit(rng)});
    }
    cached_seed = seed;
    cached_scale = scale;
  }
  return waves;
}

}  // namespace

Vec3 wind_velocity(const WindDesc& wind, const Vec3& x, double t) {
  Vec3 velocity = wind.velocity;
  const double mean_speed = wind.velocity.norm();
  if (wind.gust_amplitude != 0.0 && mean_speed > 0.0) {
    velocity += (wind.gust_amplitude * std::sin(2.0 * std::numbers::pi * t / wind.gust_period) /
                 mean_speed) *
                wind.velocity;
  }
  if (wind.turbulence != 0.0) {
    // Frozen turbulence carried by the mean flow: each wave is a function of x − w̄ t. A sum of
    // K unit sines has RMS √(K/2); the amplitude is scaled so the RMS per component matches.
    const std::vector<TurbulenceWave>& waves = turbulence_waves(wind.seed, wind.turbulence_scale);
    const Vec3 carried = x - t * wind.velocity;
    const double scale = wind.turbulence / std::sqrt(0.5 * kTurbulenceWaves);
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (int k = 0; k < kTurbulenceWaves; ++k) {
        const TurbulenceWave& wave =
            waves[static_cast<std::size_t>(c) * kTurbulenceWaves + static_cast<std::size_t>(k)];
        // A slow drift in time as well, so the noise lives even where the mean wind is calm.
        sum += std::sin(wave.wavenumber.dot(carried) + wave.phase + 0.7 * t * (k + 1));
      }
      velocity[c] += scale * sum;
    }
  }
  return velocity;
}

Vec3 face_drag(const Vec3& area_vector, const Vec3& relative_velocity, double air_density,
               double drag_coefficient) {
  const double area = area_vector.norm();
  if (area <= 0.0) {
    return Vec3::Zero();
  }
  const Vec3 normal = area_vector / area;
  const double normal_speed = relative_velocity.dot(normal);
  return (0.5 * air_density * drag_coefficient * area * normal_speed * std::abs(normal_speed)) *
         normal;
}

Vec3 bar_drag(const Vec3& axis, double diameter, const Vec3& relative_velocity, double air_density,
              double drag_coefficient) {
  const double length = axis.norm();
  if (length <= 0.0) {
    return Vec3::Zero();
  }
  const Vec3 t = axis / length;
  const Vec3 cross_flow = relative_velocity - relative_velocity.dot(t) * t;
  return (0.5 * air_density * drag_coefficient * diameter * length * cross_flow.norm()) *
         cross_flow;
}

void add_wind_forces(ForceContext& context) {
  const Model& model = context.model;
  const WindLoad& wind = model.wind;
  if (!wind.field.enabled) {
    return;
  }
  const State& state = context.state;
  const double rho = wind.field.air_density;
  for (const Index f : wind.faces) {
    if (!state.face_broken.empty() && state.face_broken[f] != 0) {
      continue;  // torn open: the wind passes through
    }
    const Index begin = model.face_offsets[f];
    const Index end = model.face_offsets[f + 1];
    const double count = end - begin;
    // Newell's area vector ½ Σ x_k × x_{k+1} is exact for planar polygons and the best plane
    // for warped ones; its length is the area.
    Vec3 area_vector = Vec3::Zero();
    Vec3 centroid = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    for (Index k = begin; k < end; ++k) {
      const Index node = model.face_nodes[k];
      const Index next = model.face_nodes[k + 1 < end ? k + 1 : begin];
      area_vector += 0.5 * state.x[node].cross(state.x[next]);
      centroid += state.x[node];
      velocity += state.v_half[node];
    }
    centroid /= count;
    velocity /= count;
    const Vec3 force =
        face_drag(area_vector, wind_velocity(wind.field, centroid, state.time) - velocity, rho,
                  wind.field.face_drag) /
        count;
    for (Index k = begin; k < end; ++k) {
      context.add(model.face_nodes[k], force);
    }
  }
  for (const Index b : wind.bars) {
    if (!state.bar_broken.empty() && state.bar_broken[b] != 0) {
      continue;
    }
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const Vec3 middle = 0.5 * (state.x[n0] + state.x[n1]);
    const Vec3 velocity = 0.5 * (state.v_half[n0] + state.v_half[n1]);
    const Vec3 force = 0.5 * bar_drag(state.x[n1] - state.x[n0], 2.0 * model.bar_radius[b],
                                      wind_velocity(wind.field, middle, state.time) - velocity, rho,
                                      wind.field.bar_drag);
    context.add(n0, force);
    context.add(n1, force);
  }
}

}  // namespace dinam
