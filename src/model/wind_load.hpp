#pragma once
// What the wind drags on, and the waves its turbulence is made of: built once with the model, so
// that a step only evaluates them.
#include <array>
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;
struct SceneDescription;
struct WindDesc;

// Turbulence is a sum of travelling sine waves, kTurbulenceWaves per velocity component
// (wind.hpp gives the field they make).
inline constexpr int kTurbulenceWaves = 4;

struct TurbulenceWave {
  Vec3 wavenumber;  // rad/m
  double phase;     // rad
  double drift;     // rad/s: a slow change in time as well, so the noise lives in a calm
};

// The 3 × kTurbulenceWaves waves of a seed, component by component: directions from three
// uniform draws in [−1, 1] normalised, magnitudes 2π/scale × U(0.5, 1.5), phases U(−π, π), and a
// drift of 0.7 (k + 1) rad/s for the k-th wave of a component. The same seed gives the same waves.
std::array<TurbulenceWave, 3 * kTurbulenceWaves> make_turbulence_waves(std::uint32_t seed,
                                                                       double scale);

// Fills model.wind from the scene's wind: the faces and bare bars of the objects it blows on,
// the nodes they touch with each node's faces and bars, and the turbulence's waves. Faces and
// bars must be built.
void add_wind(const SceneDescription& scene, Model& model);

}  // namespace dinam
