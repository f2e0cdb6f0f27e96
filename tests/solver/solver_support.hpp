#pragma once
// What the solver's tests share: the forces of a static problem, and a clamped steel cantilever.
#include <fmt/format.h>

#include <numbers>
#include <string>

#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam::test {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The implicit integrator's convergence: no node is left out of balance by more than this (m/s²,
// implicit_newton.hpp's kConvergedAcceleration), which bounds what each step may get wrong.
inline constexpr double kResidualAcceleration = 1e-2;

// Gravity, the springs and the ground: what a settle leaves on.
inline ForceSwitches static_forces() {
  ForceSwitches switches;
  switches.fields = false;
  switches.wind = false;
  return switches;
}

// A steel cantilever of 1 m along x at height 1 m in `segments` bars, clamped at x = 0:
// E I = 8000 N·m², ρ A = 0.785 kg/m. `scene_keys` are further top-level keys (gravity, settle).
inline Model clamped_cantilever(int segments, const std::string& scene_keys) {
  std::string points = "[[0, 0, 1]";
  for (int k = 1; k <= segments; ++k) {
    points += fmt::format(", [{}, 0, 1]", static_cast<double>(k) / segments);
  }
  points += "]";
  return build_model(scene_from_yaml(fmt::format(
      R"(version: 1
duration: 1
ground: {{contact: false}}
{}
objects:
  - name: beam
    mesh: {{polyline: {{points: {}}}, weld: off}}
    material: {{density: 7850, youngs_modulus: 2.0e11, area: 1.0e-4, area_moment: 4.0e-8}}
    pinned: {{indices: [0], clamped: true}}
    torsion: false
)",
      scene_keys, points)));
}

}  // namespace dinam::test
