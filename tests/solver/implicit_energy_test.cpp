// The implicit integrator's energy ledger (solver/implicit_energy.hpp): what backward Euler takes
// out of a linear oscillator against its closed form, and the balance with every account open,
// for both schemes.
#include "solver/implicit_energy.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "dynamics/energy.hpp"
#include "model/model.hpp"
#include "solver/implicit_integrator.hpp"
#include "solver_support.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A step's balance is off by the residual's work: at most test::kResidualAcceleration times the
// mass times how far the node moved.
using test::kResidualAcceleration;

State tracked_start(const Model& model, double h, ImplicitIntegrator& integrator) {
  State state = initial_state(model, h, {}, true);
  integrator.report_energy(state);
  return state;
}

// A mass on a spring: one bar along x, pinned at one end, without gravity, for backward Euler;
// `motion` sets it going (an object key). Its free node has m = ρ A L / 2 and the bar k = E A / L.
Model mass_on_a_spring(const std::string& motion) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
fps: 20
integrator: implicit
gravity: [0, 0, 0]
ground: {{contact: false}}
objects:
  - mesh: {{polyline: {{points: [[0, 0, 1], [1, 0, 1]]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e6, radius: 0.01}}
    pinned: {{indices: [0]}}
    {}
)",
                                                       motion)));
}

// A mass on a spring: one bar along x, pinned at one end, its other end thrown along it at
// v0 = 1 m/s, without gravity. Its free node has m = ρ A L / 2 and the bar k = E A / L, so
// ω² = 2E/(ρL²) = 2000 s⁻², whatever the radius. Backward Euler maps (ωx, v) by a rotation
// scaled by 1/√(1 + ω²h²), so at ωh = 1 the energy halves each step exactly: after N steps
// ½ m v0² 2^−N is left, and the rest is the scheme's (numerical_dissipation). Each step may be
// off by the residual's work, at most m × kResidualAcceleration × h v0 (the speed never grows).
TEST(ImplicitEnergy, BackwardEulerTakesOutOfAnOscillatorWhatItsClosedFormSays) {
  const Model model = mass_on_a_spring("initial_velocity: [1, 0, 0]");
  const double omega = std::sqrt(2.0 * 1.0e6 / 1000.0);
  const double h = 1.0 / omega;
  const double mass = model.node_mass[1];
  const double start = 0.5 * mass;  // ½ m v0², J
  ImplicitIntegrator integrator(model);
  State state = tracked_start(model, h, integrator);
  EXPECT_NEAR(state.energy_workspace.last.kinetic, start, 1e-15);
  for (int steps = 1; steps <= 6; ++steps) {
    integrator.advance(state, h, 1);
    const EnergyReport& report = state.energy_workspace.last;
    const double left = start * std::pow(0.5, steps);
    const double bound = steps * mass * kResidualAcceleration * h;
    std::printf("step %d: kinetic + axial %.9g J (closed form %.9g), numerical %.9g J\n", steps,
                report.kinetic + report.axial, left, report.accounts.numerical_dissipation);
    EXPECT_NEAR(report.kinetic + report.axial, left, bound) << steps;
    EXPECT_NEAR(report.accounts.numerical_dissipation, start - left, bound) << steps;
    EXPECT_NEAR(report.total, start, bound) << steps;
    EXPECT_NEAR(report.time, steps * h, 1e-12);
  }
}

// The same mass on a spring, at rest, its pinned end shaken along the bar (1 cm at 2 Hz) at
// steps of 12.5 ms (ωh = 0.56). The potential, ½ k u² in the extension u = x₁ − x₀ − L, is
// quadratic in both nodes, so backward Euler takes out of each step exactly ½ m Δv₁² + ½ k Δu²
// (the velocity's jump and the potential's Bregman divergence, the pinned node's move included),
// and the support, placed at t_{n+1}, does F_P(x_{n+1})·(x₀,ₙ − x₀,ₙ₊₁) = k uₙ₊₁ (x₀,ₙ − x₀,ₙ₊₁)
// on it. Both against those closed forms, each step off by at most the residual's work.
TEST(ImplicitEnergy, BackwardEulerBooksAShakenSupportsWorkAsItsClosedFormSays) {
  const Model model = mass_on_a_spring(
      "pin_motion: {displacement: [0.01, 0, 0], profile: {type: sine, frequency: 2}}");
  const double h = 1.0 / 80.0;
  const double mass = model.node_mass[1];
  const double k = model.bar_axial_stiffness[0];
  const double rest = model.bar_rest_length[0];
  ImplicitIntegrator integrator(model);
  State state = tracked_start(model, h, integrator);
  double numerical = 0.0;  // J, the closed forms' sums
  double support = 0.0;
  double bound = 0.0;
  for (int steps = 1; steps <= 40; ++steps) {
    const Vec3 pin = state.x[0];
    const Vec3 node = state.x[1];
    const Vec3 velocity = state.velocity[1];
    integrator.advance(state, h, 1);
    const double extension = state.x[1].x() - state.x[0].x() - rest;
    const double extension_before = node.x() - pin.x() - rest;
    numerical += 0.5 * mass * (state.velocity[1] - velocity).squaredNorm() +
                 0.5 * k * (extension - extension_before) * (extension - extension_before);
    support += k * extension * (pin.x() - state.x[0].x());
    bound += mass * kResidualAcceleration * (state.x[1] - node).norm();
  }
  const EnergyAccounts& a = state.energy_workspace.last.accounts;
  std::printf(
      "numerical %.9g J (closed form %.9g), support %.9g J (closed form %.9g), bound %.2g\n",
      a.numerical_dissipation, numerical, a.support_work, support, bound);
  ASSERT_EQ(integrator.stats().splits, 0);
  EXPECT_GT(std::abs(support), 10.0 * bound);  // a support booked as numerical loss would show
  EXPECT_NEAR(a.numerical_dissipation, numerical, bound);
  EXPECT_NEAR(a.support_work, support, bound);
  EXPECT_NEAR(state.energy_workspace.last.total, 0.0, bound);
}

// One second of `model` at steps of 12.5 ms with the energy tracked: the report at its start
// and end, and how far the balance may stray by the residuals' work, at most
// kResidualAcceleration × Σ m |Δx| over the steps, bounded by the free mass times twice the longest
// move of a node over each frame, summed over the frames (the factor 2 covers a path that turns
// within a frame).
struct TrackedSecond {
  EnergyReport start;
  EnergyReport end;
  double bound = 0.0;  // J
};

TrackedSecond track_a_second(const Model& model) {
  const double h = 1.0 / 80.0;
  ImplicitIntegrator integrator(model, {.longest_step = h});
  State state = tracked_start(model, h, integrator);
  TrackedSecond run;
  run.start = state.energy_workspace.last;
  double free_mass = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    free_mass += model.pinned(i) ? 0.0 : model.node_mass[i];
  }
  double paths = 0.0;  // m
  for (int frame = 0; frame < 20; ++frame) {
    const std::vector<Vec3> before = state.x;
    integrator.advance(state, h, 4);
    double longest = 0.0;
    for (std::size_t i = 0; i < before.size(); ++i) {
      longest = std::max(longest, (state.x[i] - before[i]).norm());
    }
    paths += longest;
  }
  run.end = state.energy_workspace.last;
  run.bound = kResidualAcceleration * free_mass * 2.0 * paths;
  return run;
}

// Everything that books energy at once, with either scheme: a yielding cloth thrown sideways
// onto the ground (gravity, the ground's penalty, friction and restitution, the springs' flow),
// under a sideways field and a wind, with axial and global dampers, and a wire dropped onto it
// (contact between objects, with its friction). The balance holds but for the residuals' work
// (track_a_second's bound).
class ImplicitEnergyBalance : public ::testing::TestWithParam<const char*> {};

TEST_P(ImplicitEnergyBalance, HoldsWithEveryAccountOpen) {
  const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
fps: 20
integrator: {}
damping: {{global: 0.5}}
wind: {{velocity: [2, 0, 0]}}
forces:
  - {{acceleration: [0, 1, 0], profile: {{type: step, start: 0.2}}}}
contact: {{objects: true}}
objects:
  - name: cloth
    mesh: {{grid: {{width: 0.4, height: 0.4, columns: 8, rows: 8}}, translation: [0, 0, 0.05]}}
    material: {{density: 1200, youngs_modulus: 2.0e6, radius: 0.002, yield_stress: 2.0e2}}
    damping: {{axial_ratio: 0.05}}
    initial_velocity: [1, 0, 0]
  - name: wire
    mesh: {{polyline: {{points: [[0.1, 0.05, 0.15], [0.1, 0.35, 0.15]], segments: 4}}}}
    material: {{density: 2000, youngs_modulus: 1.0e7, radius: 0.004}}
)",
                                                                    GetParam())));
  const TrackedSecond run = track_a_second(model);
  const double start = run.start.total;
  const double bound = run.bound;
  const EnergyReport& report = run.end;
  const EnergyAccounts& a = report.accounts;
  std::printf(
      "%s: total %.6g J from %.6g J (bound %.3g J); kinetic %.4g, contact %.4g, damping %.4g, "
      "plastic %.4g, friction %.4g, wind %.4g, field %.4g, numerical %.4g J\n",
      GetParam(), report.total, start, bound, report.kinetic, report.contact, a.damping_work,
      a.plastic_dissipation, a.friction_work, a.wind_work, a.field_work, a.numerical_dissipation);
  // Each account is open.
  EXPECT_LT(a.damping_work, 0.0);
  EXPECT_GT(a.plastic_dissipation, 0.0);
  EXPECT_LT(a.friction_work, 0.0);
  EXPECT_NE(a.wind_work, 0.0);
  EXPECT_GT(a.field_work, 0.0);
  EXPECT_NE(a.numerical_dissipation, 0.0);
  EXPECT_NEAR(report.total, start, bound);
}

// A rod clamped at one end and bent by a tip force that passes its plastic moment (σ_y Z / L =
// 0.13 N against 0.5 N): it folds at a hinge by the clamp, where a third of the field's work goes
// into the flow (0.09 J), and the balance, from zero, still holds to the same bound as above.
TEST_P(ImplicitEnergyBalance, HoldsThroughAPlasticHinge) {
  const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
fps: 20
integrator: {}
gravity: [0, 0, 0]
ground: {{contact: false}}
damping: {{global: 2}}
forces:
  - {{force: [0, 0, -0.5], object: rod, nodes: {{indices: [10]}}, profile: {{type: ramp, end: 0.5}}}}
objects:
  - name: rod
    mesh: {{polyline: {{points: [[0, 0, 1], [1, 0, 1]], segments: 10}}}}
    material: {{density: 1000, youngs_modulus: 1.0e8, radius: 0.01, yield_stress: 1.0e5}}
    pinned: {{indices: [0, 1]}}
)",
                                                                    GetParam())));
  const TrackedSecond run = track_a_second(model);
  const double bound = run.bound;
  const EnergyReport& report = run.end;
  const EnergyAccounts& a = report.accounts;
  std::printf(
      "%s: total %.6g J (bound %.3g J); field %.4g, plastic %.4g, damping %.4g, "
      "numerical %.4g, elastic %.4g, kinetic %.4g J\n",
      GetParam(), report.total, bound, a.field_work, a.plastic_dissipation, a.damping_work,
      a.numerical_dissipation, report.axial + report.bending + report.torsion, report.kinetic);
  EXPECT_GT(a.plastic_dissipation, 0.2 * a.field_work);
  EXPECT_EQ(run.start.total, 0.0);
  EXPECT_NEAR(report.total, 0.0, bound);
}

// A rod with axial dampers swinging from a support shaken up and down (5 cm at 2 Hz), the damper
// on the support pulled by its move (dynamics/axial_damper_implicit.hpp). The support is placed at
// t_{n+1} before each step, so the springs on it take its move as energy: booked as the
// support's work, F_P·(x_n − x_{n+1}) at the pinned node, the balance holds to the same bound as
// above, while the support moves far more energy than that (left out, the balance strayed by it:
// the numerical dissipation took it instead).
TEST_P(ImplicitEnergyBalance, HoldsWithASupportShaken) {
  const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
fps: 20
integrator: {}
ground: {{contact: false}}
objects:
  - name: rod
    mesh: {{polyline: {{points: [[0, 0, 2], [1, 0, 2]], segments: 10}}}}
    material: {{density: 2000, youngs_modulus: 2.0e8, radius: 0.005}}
    damping: {{axial_ratio: 0.05}}
    pinned: {{indices: [0]}}
    pin_motion: {{displacement: [0, 0, 0.05], profile: {{type: sine, frequency: 2}}}}
)",
                                                                    GetParam())));
  const TrackedSecond run = track_a_second(model);
  const EnergyReport& report = run.end;
  const EnergyAccounts& a = report.accounts;
  std::printf(
      "%s: total %.6g J from %.6g J (bound %.3g J); support %.4g, damping %.4g, numerical %.4g, "
      "kinetic %.4g J\n",
      GetParam(), report.total, run.start.total, run.bound, a.support_work, a.damping_work,
      a.numerical_dissipation, report.kinetic);
  EXPECT_GT(std::abs(a.support_work), 10.0 * run.bound);
  EXPECT_LT(a.damping_work, 0.0);
  EXPECT_NEAR(report.total, run.start.total, run.bound);
}

INSTANTIATE_TEST_SUITE_P(Schemes, ImplicitEnergyBalance,
                         ::testing::Values("implicit", "implicit_bdf2"));

}  // namespace
}  // namespace dinam
