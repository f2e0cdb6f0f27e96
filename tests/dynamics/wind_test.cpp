// Aerodynamic drag against the closed-form motion of a body carried off by a steady wind.
#include "dynamics/wind.hpp"
#include "dynamics/wind_field.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A body of mass m under drag ½ ρ Cd A (w − v)² starts at rest: dv/dt = β (w − v)² with
// β = ½ ρ Cd A / m, so v(t) = w − 1 / (1/w + β t).
double carried_speed(double wind, double beta, double t) {
  return wind - 1.0 / (1.0 / wind + beta * t);
}

// Runs the model and returns the mean x-velocity of its nodes at `duration`.
double mean_speed_after(const Model& model, double duration) {
  const double dt = std::min(1e-3, kAutoTimestepSafety * critical_timestep(model));
  State state = initial_state(model, dt);
  while (state.time < duration - 0.5 * dt) {
    step(model, dt, {}, state);
  }
  Vec3 v = Vec3::Zero();
  for (const Vec3& vi : state.velocity) {
    v += vi;
  }
  return v.x() / static_cast<double>(state.velocity.size());
}

TEST(Wind, PlateFacingTheWindIsCarriedOffAsDragPredicts) {
  // A 1 m × 1 m square plate of 4 bars facing +x, no gravity, wind 10 m/s along +x.
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {contact: false}
wind: {velocity: [10, 0, 0], face_drag: 1.2}
objects:
  - mesh: {grid: {width: 1, height: 1, columns: 1, rows: 1, diagonals: none}, rotation: [0, 90, 0]}
    material: {density: 1000, youngs_modulus: 1.0e9, radius: 0.005}
    bending_pairs: none
    torsion: false
)"));
  ASSERT_EQ(model.wind.faces.size(), 1u);
  ASSERT_TRUE(model.wind.bars.empty());  // every bar borders the face
  const double beta = 0.5 * 1.225 * 1.2 * 1.0 / model.total_mass();
  // The velocities are at half steps: compare at t − Δt/2 with Δt = 1 ms, a 1e-4 effect here.
  const double speed = mean_speed_after(model, 0.5);
  EXPECT_NEAR(speed / carried_speed(10.0, beta, 0.5), 1.0, 2e-3);
}

TEST(Wind, BareBarFeelsCrossFlowDragOnly) {
  // A bar across the wind takes ½ ρ Cd D L w²; the same bar along the wind takes nothing.
  const std::string scene = R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {{contact: false}}
wind: {{velocity: [10, 0, 0], bar_drag: 1.2}}
objects:
  - mesh: {{polyline: {{points: [[0, 0, 0], {}]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e9, radius: 0.01}}
)";
  const Model across =
      build_model(test::scene_from_yaml(fmt::format(fmt::runtime(scene), "[0, 1, 0]")));
  const double beta = 0.5 * 1.225 * 1.2 * 0.02 * 1.0 / across.total_mass();
  EXPECT_NEAR(mean_speed_after(across, 0.5) / carried_speed(10.0, beta, 0.5), 1.0, 2e-3);
  const Model along =
      build_model(test::scene_from_yaml(fmt::format(fmt::runtime(scene), "[1, 0, 0]")));
  EXPECT_NEAR(mean_speed_after(along, 0.5), 0.0, 1e-12);
}

TEST(Wind, TurbulenceIsSeededSmoothAndOfTheGivenStrength) {
  WindDesc wind;
  wind.enabled = true;
  wind.velocity = Vec3(5, 0, 0);
  wind.turbulence = 1.5;
  wind.seed = 7;
  const Vec3 p(0.3, -1.2, 2.0);
  EXPECT_EQ(wind_velocity(wind, p, 1.25), wind_velocity(wind, p, 1.25));  // deterministic
  WindDesc other = wind;
  other.seed = 8;
  EXPECT_NE(wind_velocity(wind, p, 1.25), wind_velocity(other, p, 1.25));
  // Smooth: a millisecond later it has barely changed.
  EXPECT_LT((wind_velocity(wind, p, 1.251) - wind_velocity(wind, p, 1.25)).norm(), 0.1);
  // Its RMS per component over many places and times is near the amplitude asked for.
  double sum_squares = 0.0;
  int samples = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 q(0.37 * i, std::sin(i) * 3.0, 0.11 * (i % 17));
    const Vec3 gust = wind_velocity(wind, q, 0.013 * i) - wind.velocity;
    sum_squares += gust.squaredNorm();
    samples += 3;
  }
  EXPECT_NEAR(std::sqrt(sum_squares / samples) / wind.turbulence, 1.0, 0.25);
}

}  // namespace
}  // namespace dinam
