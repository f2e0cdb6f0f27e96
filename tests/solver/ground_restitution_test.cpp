// The ground's restitution with the implicit integrator (dynamics/contact/ground_restitution.hpp):
// its law against the spring–dashpot's motion integrated numerically, and a bar dropped on the
// ground at steps of 12.5 ms, hundreds of impacts long, bouncing as central differences bounce it.
#include "dynamics/contact/ground_restitution.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dynamics/restitution.hpp"
#include "model/model.hpp"
#include "solver/implicit_integrator.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A unit mass struck onto a spring of ω = 1 and a damper of ratio ζ at unit speed, the force
// clipped at zero, integrated by classical Runge–Kutta at 10⁻⁵ of a period until it lets go:
// the speed it leaves with, to 1e-6.
double integrated_restitution(double zeta) {
  double x = 0.0;  // penetration
  double v = 1.0;  // its rate
  const double dt = 1e-5;
  auto accel = [&](double px, double pv) { return -std::max(px + 2.0 * zeta * pv, 0.0); };
  for (int k = 0; k < 10'000'000; ++k) {
    const double a1 = accel(x, v);
    const double a2 = accel(x + 0.5 * dt * v, v + 0.5 * dt * a1);
    const double a3 = accel(x + 0.5 * dt * (v + 0.5 * dt * a1), v + 0.5 * dt * a2);
    const double a4 = accel(x + dt * (v + 0.5 * dt * a2), v + dt * a3);
    x += dt * (v + dt * (a1 + a2 + a3) / 6.0);
    v += dt * (a1 + 2.0 * a2 + 2.0 * a3 + a4) / 6.0;
    if (x + 2.0 * zeta * v <= 0.0 && v < 0.0) {
      return -v;
    }
  }
  return 0.0;
}

TEST(GroundRestitution, IsTheClippedSpringDashpotsRebound) {
  for (const double zeta : {0.0, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9}) {
    EXPECT_NEAR(spring_dashpot_restitution(zeta), integrated_restitution(zeta), 1e-4) << zeta;
  }
  EXPECT_EQ(spring_dashpot_restitution(1.0), 0.0);
  EXPECT_NEAR(spring_dashpot_restitution(0.3), test::restitution_of(0.3), 1e-12);
}

// A bar dropped flat on the ground at 1 m/s, without gravity, with `integrator: implicit` at
// 12.5 ms steps (the impact lasts a third of one), rebounds at the restitution of the ground's
// damping ratio, as central differences' resolved impact does (Contact.ReboundOnTheGround…):
// from eight heights a step's travel apart in eighths. The speed it struck at is exact here (no
// gravity), and by the next step's end it is above the plane, where the penalty pushes no more:
// to 0.5 %.
TEST(GroundRestitution, ABarDroppedAtImplicitStepsReboundsAtItsDampingRatio) {
  for (const double zeta : {0.1, 0.3, 0.5}) {
    const double expected = test::restitution_of(zeta);
    const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
fps: 20
integrator: implicit
gravity: [0, 0, 0]
ground: {{damping_ratio: {}}}
objects:
  - mesh: {{polyline: {{points: [[0, 0, 0.1], [0.2, 0, 0.1]]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e8, radius: 0.005}}
    initial_velocity: [0, 0, -1]
)",
                                                                      zeta)));
    const double h = 1.0 / 80.0;
    double lowest = 1.0;
    double highest = 0.0;
    for (int drop = 0; drop < 8; ++drop) {
      State state = initial_state(model, h);
      for (Vec3& x : state.x) {
        x.z() += h * drop / 8.0;  // it lands an eighth of a step later
      }
      ImplicitIntegrator integrator(model, {.longest_step = h});  // the ground as a run has it
      integrator.advance(state, h, 16);  // lands within the 8th or 9th step; 0.2 s in all
      const double rebound = state.velocity[0].z();
      lowest = std::min(lowest, rebound);
      highest = std::max(highest, rebound);
    }
    std::printf("ground, damping ratio %.1f: restitution %.4f to %.4f, closed form %.4f\n", zeta,
                lowest, highest, expected);
    EXPECT_NEAR(lowest, expected, 0.005 * expected) << zeta;
    EXPECT_NEAR(highest, expected, 0.005 * expected) << zeta;
  }
}

// A stiff piece landing corner first: a rubber wire of 4 mm bars bent in a square, dropped tilted.
// Each node that lands is sent back up alone at its restitution (ground_restitution.hpp) while
// its neighbours still fall, so the next step's x̂ stretches its bars by a rebound's h v, many
// times their length: from there Newton's method crawled (950 Newton iterations over the
// second, the step split 11 times, against 352 and 3 from the start without the rebounds'
// velocities, which the integrator takes where its energy is lower). Where it starts changes not
// where it ends: the wire comes to rest lying flat, every node sunk into the ground by its weight
// over the softened penalty, g/ω_c² with ω_c h = kImplicitGroundFrequency (15.3 µm), to a
// micrometre. Bounds: half again the iterations first measured (352), and under the 11 splits
// of the slowed start: where a step splits hangs on the factorisations' last bits (CHOLMOD's
// kernels differ from CPU to CPU): 409 iterations and 6 splits in the release build, 453 and 9
// under the sanitizers, on the same machine.
TEST(GroundRestitution, AStiffWireLandingCornerFirstIsNotSlowedByItsNodesRebounds) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
fps: 20
integrator: implicit
objects:
  - mesh: {polyline: {points: [[0, 0, 0.15], [0.094, 0, 0.1158], [0.1111, 0.0866, 0.1628],
                               [0.0171, 0.0866, 0.197], [0.0051, 0.026, 0.1641]], segments: 100}}
    material: {density: 1100, youngs_modulus: 5.0e7, radius: 0.004}
)"));
  const double h = 1.0 / 80.0;
  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model, {.longest_step = h});
  integrator.advance(state, h, 80);
  const ImplicitStats& stats = integrator.stats();
  std::printf("stiff wire landing corner first: %lld Newton iterations, %lld splits over 1 s\n",
              static_cast<long long>(stats.iterations), static_cast<long long>(stats.splits));
  EXPECT_LE(stats.iterations, 530);
  EXPECT_LE(stats.splits, 10);
  const double omega = kImplicitGroundFrequency / h;
  const double resting = 0.004 - 9.81 / (omega * omega);
  double lowest = 1.0;
  double highest = 0.0;
  for (const Vec3& x : state.x) {
    lowest = std::min(lowest, x.z());
    highest = std::max(highest, x.z());
  }
  std::printf("its nodes at rest from %.2f to %.2f µm below its radius, g/ω_c² %.2f µm\n",
              1e6 * (0.004 - highest), 1e6 * (0.004 - lowest), 1e6 * (0.004 - resting));
  EXPECT_NEAR(lowest, resting, 1e-6);
  EXPECT_NEAR(highest, resting, 1e-6);
}

}  // namespace
}  // namespace dinam
