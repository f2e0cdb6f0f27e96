// The bars held as constraints (`integrator: xpbd`, dynamics/bar_constraints.hpp) against closed
// forms: a compliant bar hangs a mass at its spring's static stretch m g / k; a stiff bar swings as
// the pendulum, 2π √(L/g); a bar that yields lets the mass fall at g − N_y / m; the energy the
// projection takes out is booked, so the balance holds; and the step is the other springs',
// the bars left out of the bound.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// One bar of `length` hanging from a pin at z = 2 along `direction` (a unit vector in x-z): its
// free node carries half the bar's mass (ρ A L / 2), its spring k = E A / L.
Model hanging_bar(double length, const Vec3& direction, const std::string& material,
                  const std::string& scene_keys = "") {
  const Vec3 end = Vec3(0, 0, 2) + length * direction;
  return build_model(
      test::scene_from_yaml(fmt::format(R"(version: 1
duration: 10
integrator: xpbd
ground: {{contact: false}}
{}
objects:
  - name: bar
    mesh: {{polyline: {{points: [[0, 0, 2], [{}, {}, {}]]}}}}
    material: {}
    pinned: {{indices: [0]}}
    torsion: false
)",
                                        scene_keys, end.x(), end.y(), end.z(), material)));
}

double bar_length(const Model& model, const State& state) {
  return (state.x[model.bar_nodes[1]] - state.x[model.bar_nodes[0]]).norm();
}

// E A = 1000 N on a 1 m bar, k = 1000 N/m; ρ A L / 2 = 0.05 kg at the free node. Damped by the
// global friction, the mass comes to rest at the spring's static stretch m g / k = 0.4905 mm: the
// projection's fixed point is C = −α̃ λ, λ = m g h² a step, whatever the step.
TEST(BarConstraints, ACompliantBarHangsAMassAtItsSpringsStaticStretch) {
  const Model model =
      hanging_bar(1.0, Vec3(0, 0, -1), "{density: 1000, youngs_modulus: 1.0e7, area: 1.0e-4}",
                  "damping: {global: 20}");
  ASSERT_TRUE(model.bars_are_constraints());
  const double dt = choose_timestep(model, std::nullopt, 24.0, {}).dt;
  State state = initial_state(model, dt);
  advance_steps(model, dt, {}, state, std::lround(3.0 / dt));
  const double mass = model.node_mass[1];
  const double expected = mass * 9.81 / model.bar_axial_stiffness[0];
  // The friction's creep has died out (e^{−20 × 3}); rounding is far below 1e-6 of the stretch.
  EXPECT_NEAR(bar_length(model, state) - 1.0, expected, 1e-6 * expected);
}

// A steel bar of 1 m (k = 2e7 N/m, ω_bar h ≫ 1: a rigid bar to the step) released 5° from
// hanging: the pendulum of a point mass at its end, T = 2π √(L/g) (1 + θ₀²/16), within 0.3 %
// (the step's error is (ω h)² ≈ 1e-5; the small-angle series' next term is 1e-5).
TEST(BarConstraints, AStiffBarSwingsAsThePendulum) {
  const double angle = 5.0 * std::numbers::pi / 180.0;
  const Model model = hanging_bar(1.0, Vec3(std::sin(angle), 0, -std::cos(angle)),
                                  "{density: 7850, youngs_modulus: 2.0e11, area: 1.0e-4}");
  const double dt = 1e-4;
  State state = initial_state(model, dt);
  double previous_x = state.x[1].x();
  std::vector<double> crossings;  // where x passes 0 going up (towards +x)
  while (state.time < 6.0) {
    advance_steps(model, dt, {}, state, 1);
    const double x = state.x[1].x();
    if (previous_x < 0.0 && x >= 0.0) {
      crossings.push_back(state.time - dt * x / (x - previous_x));
    }
    previous_x = x;
  }
  ASSERT_GE(crossings.size(), 2u);
  const double period =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double expected =
      2.0 * std::numbers::pi * std::sqrt(1.0 / 9.81) * (1.0 + angle * angle / 16.0);
  EXPECT_NEAR(period, expected, 3e-3 * expected);
  // And the bar stayed rigid to its spring's stretch under the swing's tension (m g ≈ 3.85 N,
  // the centripetal part 1 %): T / k below 3e-7 m.
  EXPECT_NEAR(bar_length(model, state), 1.0, 3e-7);
}

// A bar of yield force N_y = 0.2 N carrying a mass of 0.05 kg (weight 0.49 N): it flows from the
// first step, its tension held at N_y, and the mass falls at g − N_y / m = 5.81 m/s².
TEST(BarConstraints, ABarAtItsYieldForceLetsTheMassFallAtWhatIsLeftOfGravity) {
  const Model model = hanging_bar(1.0, Vec3(0, 0, -1),
                                  "{density: 1000, youngs_modulus: 1.0e7, area: 1.0e-4, yield: "
                                  "{axial: 0.2}}");
  ASSERT_TRUE(model.bars_yield);
  const double dt = choose_timestep(model, std::nullopt, 24.0, {}).dt;
  State state = initial_state(model, dt);
  const double mass = model.node_mass[1];
  advance_steps(model, dt, {}, state, std::lround(0.2 / dt));
  const double z0 = state.x[1].z();
  const double v0 = state.velocity[1].z();
  const auto steps = std::lround(0.3 / dt);
  advance_steps(model, dt, {}, state, steps);
  const double t = static_cast<double>(steps) * dt;
  // Leapfrog under a constant acceleration a, its velocity v_{n−½} half a step behind:
  // z_{n+k} = z_n + k h v_{n−½} − a h² k (k + 1) / 2, exactly.
  const double accel = 2.0 * (z0 + v0 * t - state.x[1].z()) / (t * t + dt * t);
  EXPECT_NEAR(accel, 9.81 - 0.2 / mass, 1e-3 * 9.81);
  EXPECT_GT(state.bar_plastic_set[0], 0.1);  // it flowed: the bar is longer for good
}

// The energy the projection takes out (its impulses' work less what the bars would store) is
// booked as numerical dissipation: an undamped chain of stiff bars swinging from level keeps its
// balance within 0.1 % of its peak kinetic energy, while the dissipation booked is larger.
TEST(BarConstraints, TheProjectionsShareOfTheEnergyIsBooked) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
integrator: xpbd
ground: {contact: false}
objects:
  - name: chain
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e9, radius: 0.005}
    pinned: {indices: [0]}
)"));
  const double dt = choose_timestep(model, std::nullopt, 24.0, {}).dt;
  State state = initial_state(model, dt, {}, true);
  const double start = state.energy_workspace.last.total;
  double peak_kinetic = 0.0;
  double worst = 0.0;
  for (int s = 0; s < std::lround(1.5 / dt); ++s) {
    step(model, dt, {}, state);
    const EnergyReport& report = state.energy_workspace.last;
    peak_kinetic = std::max(peak_kinetic, report.kinetic);
    worst = std::max(worst, std::abs(report.total - start));
  }
  EXPECT_LT(worst, 1e-3 * peak_kinetic);
  EXPECT_GT(state.energy.numerical_dissipation, 1e-3 * peak_kinetic);
}

// The step is the other springs': a bar's own spring bounds no step (its frequency left out of
// the bound), its damper no damping rate; the same model as central differences sees it is
// bounded by the bar.
TEST(BarConstraints, TheBarsBoundNoStep) {
  const Model model =
      hanging_bar(1.0, Vec3(0, 0, -1), "{density: 7850, youngs_modulus: 2.0e11, radius: 0.005}");
  EXPECT_EQ(max_frequency_squared_bound(model), 0.0);  // one bar, no other spring
  EXPECT_GT(max_frequency_squared_bound(model, true, BarsIn::kSprings), 1e7);  // k / m, 5e7
}

}  // namespace
}  // namespace dinam
