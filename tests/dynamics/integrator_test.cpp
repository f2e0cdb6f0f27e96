#include "dynamics/integrator.hpp"
#include "stepping/time_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "test_support.hpp"
#include "tolerances.hpp"

namespace dinam {
namespace {

// One bar along x from a pinned node to a free one: a single mass on a spring. With ρ = 1000,
// A = 1e-4, L = 1, E = 1e6: k = EA/L = 100 N/m, m = ρAL/2 = 0.05 kg, ω = √(k/m) = √2000 rad/s.
// `more` adds keys to the object, each line indented by four spaces.
Model spring_mass_model(double initial_speed, const std::string& more = "") {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
gravity: [0, 0, 0]
objects:
  - mesh: {{polyline: {{points: [[0, 0, 0], [1, 0, 0]]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e6, area: 1.0e-4}}
    pinned: {{indices: [0]}}
    initial_velocity: [{}, 0, 0]
{})",
                                                       initial_speed, more)));
}

constexpr double kSpringOmega = 44.721359549995796;  // √2000

// Times of the upward zero crossings of the free node's displacement, linearly interpolated.
std::vector<double> upward_crossings(const Model& model, double dt, int steps) {
  State state = initial_state(model, dt);
  const ForceSwitches forces;
  std::vector<double> crossings;
  double previous = state.x[1].x() - 1.0;
  for (int n = 0; n < steps; ++n) {
    step(model, dt, forces, state);
    const double u = state.x[1].x() - 1.0;
    if (previous < 0.0 && u >= 0.0) {
      crossings.push_back(state.time - dt * u / (u - previous));
    }
    previous = u;
  }
  return crossings;
}

TEST(Integrator, SpringMassOscillatesAtItsNaturalFrequency) {
  const Model model = spring_mass_model(-0.1);  // start moving left, so it crosses upwards
  ASSERT_NEAR(model.node_mass[1], 0.05, 1e-15);
  ASSERT_NEAR(model.bar_axial_stiffness[0], 100.0, 1e-12);
  const double period = 2.0 * std::numbers::pi / kSpringOmega;
  const double dt = period / 400.0;
  const std::vector<double> crossings = upward_crossings(model, dt, 400 * 21);
  ASSERT_GE(crossings.size(), 20u);
  const double measured_period =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double measured_omega = 2.0 * std::numbers::pi / measured_period;
  EXPECT_NEAR(measured_omega / kSpringOmega, 1.0, test::kFrequencyRelative);
}

TEST(Integrator, FreeFallIsExactForConstantAcceleration) {
  // With v_{-½} = v0 − ½Δt g the leapfrog gives x_n = x0 + v0 t + ½ g t² exactly, and a rigidly
  // falling bar keeps its length, so its spring stays at rest.
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
objects:
  - mesh: {polyline: {points: [[0, 0, 10], [1, 0, 10]]}}
    material: {density: 1000, youngs_modulus: 1.0e6, area: 1.0e-4}
    initial_velocity: [1, 0, 2]
)"));
  const double dt = 1e-3;
  State state = initial_state(model, dt);
  for (int n = 0; n < 1000; ++n) {
    step(model, dt, {}, state);
  }
  const double t = state.time;
  EXPECT_DOUBLE_EQ(t, 1.0);
  const Vec3 expected = Vec3(0, 0, 10) + Vec3(1, 0, 2) * t + 0.5 * Vec3(0, 0, -9.81) * t * t;
  EXPECT_NEAR((state.x[0] - expected).norm(), 0.0, test::kRoundingRelative * expected.norm());
}

// A per-node field force switched on at t0 = 0.1 s on one free bar (both ends loaded): after it,
// each node accelerates at F/m, so x(t) = ½ (F/m) (t − t0)² exactly for the leapfrog as long as
// the switch falls on a step.
TEST(Integrator, SteppedFieldForceGivesUniformAcceleration) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {contact: false}
objects:
  - name: bar
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]]}}
    material: {density: 1000, youngs_modulus: 1.0e6, area: 1.0e-4}
forces:
  - {force: [0, 0.5, 0], object: bar, profile: {type: step, start: 0.1}}
)"));
  const double m = model.node_mass[0];  // 0.05 kg: a = 10 m/s²
  const double dt = 1e-3;
  State state = initial_state(model, dt);
  for (int n = 0; n < 600; ++n) {
    step(model, dt, {}, state);
  }
  // Leapfrog with a force from step 100 on: v_{n+½} = (n − 99) a Δt, so y_600 = a Δt² Σ_{k=1}^{500}
  // k.
  const double expected = 0.5 / m * dt * dt * 500.0 * 501.0 / 2.0;
  EXPECT_NEAR(state.x[0].y(), expected, 1e-12);
  EXPECT_NEAR(state.x[1].y(), expected, 1e-12);
}

// Tracking energy reads the forces by kind; it must not change a bit of the motion.
TEST(Integrator, TrackingEnergyDoesNotChangeTheMotion) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
damping: {global: 0.3}
ground: {friction: {static: 0.5, kinetic: 0.3}}
wind: {velocity: [3, 0, 0], turbulence: {amplitude: 1}}
forces: [{acceleration: [0, 1, 0], profile: {type: sine, frequency: 2}}]
objects:
  - mesh: {grid: {width: 0.5, height: 0.5, columns: 4, rows: 4}, translation: [0, 0, 0.2]}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.002}
    damping: {axial_ratio: 0.1}
    initial_velocity: [1, 0, -2]
)"));
  const double dt = 2e-5;
  State plain = initial_state(model, dt, {}, false);
  State tracked = initial_state(model, dt, {}, true);
  for (int n = 0; n < 5000; ++n) {
    step(model, dt, {}, plain);
    step(model, dt, {}, tracked);
  }
  EXPECT_EQ(plain.x, tracked.x);
  EXPECT_EQ(plain.velocity, tracked.velocity);
}

TEST(Integrator, PinnedNodesNeverMove) {
  const Model model = spring_mass_model(3.0);
  State state = initial_state(model, 1e-4);
  for (int n = 0; n < 5000; ++n) {
    step(model, 1e-4, {}, state);
  }
  EXPECT_EQ(state.x[0], Vec3(0, 0, 0));
}

TEST(Integrator, DivergenceStopsWithNodeStepAndTime) {
  const Model model = spring_mass_model(1.0);
  const double dt = 10.0 * 2.0 / kSpringOmega;  // ten times the stability limit
  State state = initial_state(model, dt);
  try {
    for (int n = 0; n < 100000; ++n) {
      step(model, dt, {}, state);
    }
    FAIL() << "an unstable run did not stop";
  } catch (const RuntimeError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("node 1 of object 'object0'"), std::string::npos) << message;
    EXPECT_NE(message.find(fmt::format("at step {}", state.step)), std::string::npos) << message;
    EXPECT_NE(message.find("t = "), std::string::npos) << message;
  }
}

// The central-difference limit for one oscillator is Δt = 2/ω exactly (the amplification
// matrix has |λ| = 1 below it and a real root beyond −1 above it). Just below, the motion
// stays bounded by its amplitude; just above, it grows without bound.
TEST(Integrator, StabilityLimitOfOneOscillatorIsTwoOverOmega) {
  const Model model = spring_mass_model(1.0);
  const double amplitude = 1.0 / kSpringOmega;  // v0 / ω
  auto largest_displacement = [&](double dt) {
    State state = initial_state(model, dt);
    double largest = 0.0;
    for (int n = 0; n < 3000 && largest < 1e3; ++n) {
      step(model, dt, {}, state);
      largest = std::max(largest, std::abs(state.x[1].x() - 1.0));
    }
    return largest;
  };
  // Near the limit the discrete motion's amplitude is v0 / (ω cos(ωΔt/2)-ish): a few times the
  // continuous one, never a thousand times.
  EXPECT_LT(largest_displacement(0.98 * 2.0 / kSpringOmega), 10.0 * amplitude);
  EXPECT_GT(largest_displacement(1.02 * 2.0 / kSpringOmega), 1000.0 * amplitude);
}

// A shaken support: the spring-mass with its pinned end driven as u(t) = A sin Ωt. From rest the
// mass follows y(t) = A ω²/(ω² − Ω²) (sin Ωt − (Ω/ω) sin ωt) exactly; the leapfrog's phase error
// at ωΔt = 2π/400 over seven periods is about 5e-4 rad, so 2e-3 A bounds the difference. A support
// that stayed put would miss by the whole amplitude.
TEST(Integrator, ShakenSupportDrivesTheSpringMassAsTheClosedFormSays) {
  constexpr double kAmplitude = 0.01;
  const double drive_omega = 0.5 * kSpringOmega;
  const Model model = spring_mass_model(
      0.0, fmt::format("    pin_motion: {{displacement: [{}, 0, 0], profile: {{type: sine, "
                       "frequency: {:.17g}}}}}\n",
                       kAmplitude, drive_omega / (2.0 * std::numbers::pi)));
  const double dt = 2.0 * std::numbers::pi / kSpringOmega / 400.0;
  State state = initial_state(model, dt);
  const double w2 = kSpringOmega * kSpringOmega;
  const double gain = kAmplitude * w2 / (w2 - drive_omega * drive_omega);
  double worst = 0.0;
  for (int n = 0; n < 400 * 7; ++n) {
    step(model, dt, {}, state);
    const double t = state.time;
    EXPECT_NEAR(state.x[0].x(), kAmplitude * std::sin(drive_omega * t), 1e-15);
    const double expected = gain * (std::sin(drive_omega * t) -
                                    drive_omega / kSpringOmega * std::sin(kSpringOmega * t));
    worst = std::max(worst, std::abs(state.x[1].x() - 1.0 - expected));
  }
  EXPECT_LT(worst, 2e-3 * kAmplitude);
}

// Settling: a mass hanging on a spring comes to rest at its static extension m g / k (4.905 mm)
// before t = 0. It stops once the out-of-balance force is at most 1e-8 of the weight; on a linear
// spring that force is k times the error, so the error is at most 1e-8 of the extension (with a
// hundredth of that for rounding). The sideways field waits for t = 0, so the mass has not moved
// sideways.
TEST(Integrator, SettlingHangsTheSpringMassAtItsStaticExtension) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
settle: {duration: 1.0, residual: 1.0e-8}
forces: [{acceleration: [5, 0, 0]}]
objects:
  - mesh: {polyline: {points: [[0, 0, 2], [0, 0, 1]]}}
    material: {density: 1000, youngs_modulus: 1.0e6, area: 1.0e-4}
    pinned: {indices: [0]}
)"));
  const double dt = 2.0 * std::numbers::pi / kSpringOmega / 400.0;
  const State state = initial_state(model, dt);
  const double extension = 0.05 * 9.81 / 100.0;
  EXPECT_NEAR(state.x[1].z(), 1.0 - extension, 1.01e-8 * extension);
  EXPECT_TRUE(state.settled.ran);
  EXPECT_LE(state.settled.residual, 1e-8);
  EXPECT_LT(state.settled.steps, std::llround(1.0 / dt));  // it stopped once converged
  EXPECT_EQ(state.x[1].x(), 0.0);
  EXPECT_EQ(state.time, 0.0);
  EXPECT_EQ(state.step, 0);
}

}  // namespace
}  // namespace dinam
