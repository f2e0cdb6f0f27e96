// Backward Euler (`integrator: implicit`), against numbers from outside the code: the closed form
// of backward Euler on a linear oscillator, the static equilibrium it must come to rest at, and
// the motion bit for bit on any thread count.
#include "solver/implicit_integrator.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "core/thread_team.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "solver/equilibrium.hpp"
#include "solver_support.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// One steel-free bar: node 0 pinned at the origin, node 1 at x = 1 m with the bar's half mass,
// thrown along the bar at v0 = 0.01 m/s, without gravity: a linear oscillator of ω² = (EA/L)/m
// (the axial spring is linear for motion along the bar).
Model oscillator(const std::string& integrator) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
gravity: [0, 0, 0]
integrator: {}
ground: {{contact: false}}
objects:
  - mesh: {{polyline: {{points: [[0, 0, 1], [1, 0, 1]]}}}}
    material: {{density: 1000, youngs_modulus: 2.0e5, area: 1.0e-4}}
    pinned: {{indices: [0]}}
    initial_velocity: [0.01, 0, 0]
)",
                                                       integrator)));
}

TEST(ImplicitIntegrator, AnOscillatorFollowsBackwardEulersClosedForm) {
  const Model model = oscillator("implicit");
  const double m = model.node_mass[1];            // 0.05 kg
  const double k = model.bar_axial_stiffness[0];  // 20 N/m
  const double omega = std::sqrt(k / m);          // 20 rad/s
  const double h = 0.02;                          // ω h = 0.4: 16 steps a period

  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model);
  // In (x, v/ω) a step multiplies by (1 + iωh)⁻¹: a turn by θ = atan(ωh) and a shrink by
  // ρ = 1/√(1 + ω²h²); from x = 0, v = v0: x_n = (v0/ω) ρⁿ sin(nθ).
  const double rho = 1.0 / std::sqrt(1.0 + omega * omega * h * h);
  const double theta = std::atan(omega * h);
  const double amplitude = 0.01 / omega;
  for (int n = 1; n <= 48; ++n) {
    integrator.advance(state, h, 1);
    const double expected = amplitude * std::pow(rho, n) * std::sin(n * theta);
    // Newton's method solves a linear step in one iteration, to its convergence test (1e-5 of the
    // bar's length over ω²h², 2e-6 of the amplitude here) at worst.
    EXPECT_NEAR(state.x[1].x() - 1.0, expected, 1e-6 * amplitude) << "step " << n;
  }
  EXPECT_EQ(integrator.stats().splits, 0);
  EXPECT_NEAR(state.time, 48 * h, 1e-12);
}

// The oscillator with an axial damper (a fifth of critical), its support carried along the bar
// at the node's own speed (a ramp of 1 cm over 1 s from t = 0, the node thrown at 1 cm/s): the
// two move as one body, the spring stays at its rest length and the damper sees no relative
// speed, so the node goes on at 1 cm/s exactly, x₁ = 1 m + u t. A damper that took the support
// for still would brake it by c u = 0.04 N, 0.8 m/s² on its 0.05 kg.
TEST(ImplicitIntegrator, ADamperToASupportMovingWithItsNodeDoesNotBrakeIt) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, 0]
integrator: implicit
ground: {contact: false}
objects:
  - mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]]}}
    material: {density: 1000, youngs_modulus: 2.0e5, area: 1.0e-4}
    damping: {axial_ratio: 0.2}
    pinned: {indices: [0]}
    pin_motion: {displacement: [0.01, 0, 0], profile: {type: ramp, end: 1}}
    initial_velocity: [0.01, 0, 0]
)"));
  ASSERT_GT(model.bar_damping[0], 0.0);
  const double h = 0.02;
  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model);
  for (int n = 1; n <= 40; ++n) {
    integrator.advance(state, h, 1);
    EXPECT_NEAR(state.x[0].x(), 0.01 * n * h, 1e-15) << "step " << n;
    EXPECT_NEAR(state.x[1].x(), 1.0 + 0.01 * n * h, 1e-12) << "step " << n;
  }
}

// The same oscillator with BDF2: in u = x − i v/ω, u' = iω u, and a step is (3 − 2iωh) u_{n+1} =
// 4 u_n − u_{n−1}, after one backward Euler step u_1 = u_0 / (1 − iωh). Its amplitude |u| falls by
// the principal root's |r| = |2 + √(1 + 2iωh)| / |3 − 2iωh| a step, far less than backward
// Euler's ρ: at ωh = 0.4, 0.35 % a step against 7.4 %.
TEST(ImplicitIntegrator, BDF2FollowsItsClosedFormAndDampsLessThanBackwardEuler) {
  const Model model = oscillator("implicit_bdf2");
  ASSERT_EQ(model.implicit_scheme, ImplicitScheme::kBdf2);
  const double omega = std::sqrt(model.bar_axial_stiffness[0] / model.node_mass[1]);  // 20 rad/s
  const double h = 0.02;
  const std::complex<double> z(0.0, omega * h);
  const double amplitude = 0.01 / omega;
  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model);
  std::complex<double> before(0.0, -amplitude);   // u_0
  std::complex<double> now = before / (1.0 - z);  // u_1
  integrator.advance(state, h, 1);
  EXPECT_NEAR(state.x[1].x() - 1.0, now.real(), 1e-6 * amplitude) << "step 1";
  double halfway = 0.0;  // |u_48|, from the state
  for (int n = 2; n <= 96; ++n) {
    const std::complex<double> next = (4.0 * now - before) / (3.0 - 2.0 * z);
    before = now;
    now = next;
    integrator.advance(state, h, 1);
    EXPECT_NEAR(state.x[1].x() - 1.0, now.real(), 1e-6 * amplitude) << "step " << n;
    EXPECT_NEAR(state.velocity[1].x() / omega, -now.imag(), 1e-6 * amplitude) << "step " << n;
    if (n == 48) {
      halfway = std::hypot(state.x[1].x() - 1.0, state.velocity[1].x() / omega);
    }
  }
  // Over the last 48 steps the amplitude fell as the principal root says: the other root, about
  // 1/3, has long died out.
  const double root = std::abs((2.0 + std::sqrt(1.0 + 2.0 * z)) / (3.0 - 2.0 * z));
  const double last = std::hypot(state.x[1].x() - 1.0, state.velocity[1].x() / omega);
  EXPECT_NEAR(last / halfway / std::pow(root, 48), 1.0, 1e-4);
  EXPECT_LT(1.0 - root, 0.1 * (1.0 - 1.0 / std::sqrt(1.0 + std::norm(z))));
  EXPECT_EQ(integrator.stats().splits, 0);
}

// A steel rod of 1 m pinned at one end and let go level is a pendulum swinging through 90°
// either side; its free node carries half the rod's mass and the pinned one none that moves, so
// it is a point mass on a massless rod: T = 4 √(L/g) K(sin 45°), K(1/√2) = 1.8540747, 2.3687 s.
// With BDF2 at 10 ms (237 steps a period, 35 times central differences' bound for the rod's
// stretching) the period is within 1e-3 (measured +5.8e-4) and the swing, after 2.7 periods,
// within 1 cm of level (4.7 mm below); at 2.5 ms both errors are ten times smaller (3.3e-5 and
// 0.47 mm). (When Newton stopped at 1e-5 of the bar, 1.6 m/s² of out-of-balance acceleration
// at 2.5 ms, the finer step lost half the swing: kConvergedAcceleration.)
TEST(ImplicitIntegrator, BDF2SwingsAPendulumThrough90DegreesAtItsClosedFormPeriod) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 10
integrator: implicit_bdf2
ground: {contact: false}
objects:
  - mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]]}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.005}
    pinned: {indices: [0]}
)"));
  const double period = 4.0 * std::sqrt(1.0 / 9.81) * 1.8540747;
  struct Swing {
    double period_error;  // of the second and third crossings below the pin
    double lowest_turn;   // m, the far side's turning point below the pin's height
  };
  const auto swing = [&](double h) {
    EXPECT_GT(h, 8.0 * critical_timestep(model));
    State state = initial_state(model, h);
    ImplicitIntegrator integrator(model);
    // The times it passes below the pin, by linear interpolation between steps.
    std::vector<double> crossings;
    double x_before = state.x[1].x();
    while (state.time < 2.2 * period) {
      integrator.advance(state, h, 1);
      const double x = state.x[1].x();
      if ((x_before > 0.0) != (x > 0.0)) {
        crossings.push_back(state.time - h * x / (x - x_before));
      }
      x_before = x;
    }
    EXPECT_GE(crossings.size(), 4u);
    double highest = -1.0;
    while (state.time < 2.7 * period) {
      integrator.advance(state, h, 1);
      highest = std::max(highest, state.x[1].z() - 2.0);
    }
    return Swing{(crossings.at(3) - crossings.at(1)) / period - 1.0, -highest};
  };
  const Swing coarse = swing(0.01);
  const Swing fine = swing(0.0025);
  EXPECT_LT(std::abs(coarse.period_error), 1e-3);
  EXPECT_LT(coarse.lowest_turn, 0.01);
  // A quarter of the step: BDF2's errors, of second order or more, fall at least fivefold.
  EXPECT_LT(std::abs(fine.period_error), 0.2 * std::abs(coarse.period_error));
  EXPECT_LT(fine.lowest_turn, 0.2 * coarse.lowest_turn);
}

// A bent wire falling freely, without a ground: backward Euler's closed form for a constant
// force, v_n = n h g and x_n = x_0 + h² g n(n + 1)/2, at every node. A rigid translation leaves
// the stiffness as it was, so one factorisation serves every step (the Newton steps' solve is
// preconditioned with it throughout).
TEST(ImplicitIntegrator, AFreeFallFollowsTheClosedFormOnOneFactorisation) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
integrator: implicit
ground: {contact: false}
objects:
  - mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1], [1, 1, 1.5]], segments: 12}}
    material: {density: 1000, youngs_modulus: 1.0e8, radius: 0.005}
)"));
  const double h = 0.05;
  ASSERT_GT(h, 100.0 * critical_timestep(model));
  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model);
  const int steps = 40;
  integrator.advance(state, h, steps);
  const double fall = 9.81 * h * h * steps * (steps + 1) / 2.0;  // 20.1 m
  for (Index i = 0; i < model.node_count(); ++i) {
    const Vec3 expected = model.node_initial_x[i] - Vec3(0.0, 0.0, fall);
    // Each Newton step solves the translation but for the Hessian's products, which come from
    // differences of the gradient (exact to about 1e-8 of the step's motion): what is left is
    // rounding, and that difference's error.
    EXPECT_LT((state.x[i] - expected).norm(), 1e-9 * fall) << "node " << i;
    EXPECT_NEAR(state.velocity[i].z(), -9.81 * h * steps, 1e-8 * 9.81 * h * steps) << "node " << i;
  }
  EXPECT_EQ(integrator.stats().steps, steps);
  EXPECT_EQ(integrator.stats().factorizations, 1);
}

// With dampers, a hanging rope comes to rest where Newton's method finds the equilibrium, at steps
// as long as a frame (a thousand times its explicit limit).
TEST(ImplicitIntegrator, ADampedRopeComesToRestAtTheStaticEquilibrium) {
  const SceneDescription scene = test::scene_from_yaml(R"(version: 1
duration: 1
integrator: implicit
ground: {contact: false}
objects:
  - mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e8, radius: 0.005}
    pinned: {indices: [0, 10]}
    damping: {axial_ratio: 0.5}
damping: {global: 2.0}
)");
  const Model model = build_model(scene);
  const double h = 0.05;
  ASSERT_GT(h, 100.0 * critical_timestep(model));
  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model);
  integrator.advance(state, h, 400);  // 20 s, some 40 times the slowest swing's decay time
  State equilibrium = make_state(model, false);
  const EquilibriumOutcome found =
      find_equilibrium(model, test::static_forces(), {1e-10}, equilibrium);
  ASSERT_TRUE(found.converged) << found.failure;
  double worst = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    worst = std::max(worst, (state.x[i] - equilibrium.x[i]).norm());
  }
  // The sag is about 2 cm; at rest the two agree to far less than a micrometre.
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT((equilibrium.x[5] - model.node_initial_x[5]).norm(), 1e-3);  // it sagged
}

// A cloth in the wind, pinned at one edge, sagging onto the ground (its friction) with threads
// that yield (at 200 Pa: its bending springs flow within the four steps), on 1 and 2 threads: the
// same bits, with either scheme.
class ImplicitThreads : public ::testing::TestWithParam<const char*> {};

TEST_P(ImplicitThreads, TheMotionIsTheSameBitForBitOnAnyThreadCount) {
  const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
integrator: {}
wind: {{velocity: [3, 0, 0]}}
objects:
  - mesh: {{grid: {{width: 1, height: 1, columns: 40, rows: 30}}, translation: [0, 0, 0.0015]}}
    material: {{density: 1200, youngs_modulus: 2.0e6, radius: 0.001, yield_stress: 2.0e2}}
    pinned: {{box: {{min: [-0.01, -1, 0], max: [0.01, 2, 1]}}}}
    damping: {{axial_ratio: 0.05}}
)",
                                                                    GetParam())));
  ASSERT_TRUE(worth_sharing(model));
  const auto run = [&](int threads) {
    const int before = thread_count();
    set_thread_count(threads);
    State state = initial_state(model, 0.0125);
    ImplicitIntegrator integrator(model);
    integrator.advance(state, 0.0125, 4);
    set_thread_count(before);
    return state;
  };
  const State one = run(1);
  const State two = run(2);
  EXPECT_EQ(one.x, two.x);
  EXPECT_EQ(one.bar_plastic_set, two.bar_plastic_set);
  EXPECT_EQ(one.bend_plastic_set, two.bend_plastic_set);
  EXPECT_EQ(one.torsion_plastic_set, two.torsion_plastic_set);
  EXPECT_EQ(one.contact_anchor, two.contact_anchor);
  // It moved, some of it touches the ground and some spring flowed, so the comparisons compare
  // something.
  EXPECT_NE(one.x, model.node_initial_x);
  EXPECT_GT(std::count(one.contact_touching.begin(), one.contact_touching.end(), 1), 0);
  const auto flowing = [](const std::vector<double>& sets) {
    return std::count_if(sets.begin(), sets.end(), [](double p) { return p != 0.0; });
  };
  EXPECT_GT(flowing(one.bend_plastic_set), 0);
}

INSTANTIATE_TEST_SUITE_P(Schemes, ImplicitThreads, ::testing::Values("implicit", "implicit_bdf2"));

}  // namespace
}  // namespace dinam
