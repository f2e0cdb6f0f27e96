// The force kernels one at a time: each elastic force is minus the gradient of its energy
// (finite differences), the singular configurations stay finite, plasticity and time profiles.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "core/geometry.hpp"
#include "dynamics/axial_spring.hpp"
#include "dynamics/bending_spring.hpp"
#include "dynamics/contact/ground_contact.hpp"
#include "dynamics/elastoplastic.hpp"
#include "dynamics/torsion_spring.hpp"
#include "model/model.hpp"
#include "tolerances.hpp"

namespace dinam {
namespace {

constexpr double kStep = 1e-6;  // m, finite-difference step

// Checks f_p = −∂E/∂x_p for every node p by central differences of `energy`.
template <typename Energy>
void expect_force_is_minus_gradient(std::vector<Vec3> x, const std::vector<Vec3>& force,
                                    const Energy& energy) {
  double scale = 1.0;
  for (const Vec3& f : force) {
    scale = std::max(scale, f.norm());
  }
  for (std::size_t p = 0; p < x.size(); ++p) {
    for (int c = 0; c < 3; ++c) {
      const double saved = x[p][c];
      x[p][c] = saved + kStep;
      const double plus = energy(x);
      x[p][c] = saved - kStep;
      const double minus = energy(x);
      x[p][c] = saved;
      EXPECT_NEAR(force[p][c], -(plus - minus) / (2 * kStep), test::kGradientRelative * scale)
          << "node " << p << " component " << c;
    }
  }
}

std::vector<Vec3> random_points(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  }
  return points;
}

TEST(BendingSpring, ForceIsMinusTheEnergyGradient) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const std::vector<Vec3> x = random_points(rng, 3);
    const double rest = 0.3 + 2.5 * (trial % 10) / 10.0;  // rest angles across (0, π)
    const double plastic_set = trial % 3 == 0 ? 0.2 : 0.0;
    const double k = 3.0;
    const BendingSpringResult r = bending_spring(x[0], x[1], x[2], rest, k, plastic_set);
    expect_force_is_minus_gradient(x, {r.force_a, r.force_c, r.force_b}, [&](const auto& y) {
      return bending_spring(y[0], y[1], y[2], rest, k, plastic_set).energy;
    });
  }
}

TEST(TorsionSpring, ForceIsMinusTheEnergyGradient) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 30; ++trial) {
    const std::vector<Vec3> x = random_points(rng, 4);
    const double rest = -3.0 + 6.0 * (trial % 10) / 10.0;
    const double plastic_set = trial % 3 == 0 ? -0.4 : 0.0;
    const double k = 2.0;
    const TorsionSpringResult r = torsion_spring(x[0], x[1], x[2], x[3], rest, k, plastic_set);
    expect_force_is_minus_gradient(
        x, {r.force_a, r.force_i, r.force_j, r.force_b}, [&](const auto& y) {
          return torsion_spring(y[0], y[1], y[2], y[3], rest, k, plastic_set).energy;
        });
  }
}

// A reference bar swinging into line with its bar, down to exactly in line. The force stays
// finite and is the energy's gradient everywhere, and the spring vanishes where the reference is
// lost (its weight, the sine squared, is zero there). Exactly in line the energy is
// |u|² f(u/|u|) in the reference's offset u from the line, with a twist that depends on the
// direction: continuously differentiable with zero gradient, but with no second derivative, so
// there the check is the bound E ≤ ½ k π² (|u|/|b1|)² at small offsets rather than differences.
TEST(TorsionSpring, NearCollinearReferencesKeepForceEqualToMinusTheGradient) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> twist(-3.0, 3.0);
  const double k = 2.0;
  const Vec3 xi(0.1, -0.2, 0.05);
  const Vec3 xj(1.1, 0.1, -0.1);
  const Vec3 axis = (xj - xi).normalized();
  const Vec3 across = axis.cross(Vec3(0.3, 0.2, 1.0)).normalized();
  for (const double degrees : {0.0, 1e-6, 2.0, 5.0, 5.8, 7.0, 9.0, 10.5, 11.4, 11.6, 20.0}) {
    for (int trial = 0; trial < 4; ++trial) {
      const double theta = degrees * std::numbers::pi / 180.0;
      // a behind i, at angle theta from the bar's line; b a well-placed reference at j.
      const Vec3 xa = xi - 0.7 * (std::cos(theta) * axis + std::sin(theta) * across);
      const Vec3 xb = xj + 0.6 * axis.cross(across) + 0.2 * axis;
      const double rest = twist(rng);
      const double plastic_set = trial % 2 == 0 ? 0.3 : 0.0;
      const std::vector<Vec3> x = {xa, xi, xj, xb};
      const TorsionSpringResult r = torsion_spring(xa, xi, xj, xb, rest, k, plastic_set);
      for (const Vec3& f : {r.force_a, r.force_i, r.force_j, r.force_b}) {
        ASSERT_TRUE(f.allFinite()) << degrees << "°";
      }
      // Within a few finite-difference steps of the line, the bound (the energy's gradient is
      // zero on the line itself, and within 1e-7 of it just off).
      const double off_line = 0.7 * std::sin(theta);  // m, the reference's offset from the line
      if (off_line < 10.0 * kStep) {
        EXPECT_LT(r.force_a.norm(), 1e-7) << degrees << "°";
        for (const double offset : {0.0, 1e-3, 1e-5}) {
          for (const Vec3& direction : {across, axis.cross(across), (across - axis).eval()}) {
            const Vec3 moved = xa + offset * direction.normalized();
            // At most; the points themselves are off the line by their rounding, a few 1e-16 m
            // (where the energy, a sine squared, is then of order 1e-32 J).
            const double sine = (off_line + offset + 1e-15) / 0.7;
            EXPECT_LE(torsion_spring(moved, xi, xj, xb, rest, k, plastic_set).energy,
                      0.5 * k * std::numbers::pi * std::numbers::pi * sine * sine)
                << degrees << "°";
          }
        }
        continue;
      }
      expect_force_is_minus_gradient(
          x, {r.force_a, r.force_i, r.force_j, r.force_b}, [&](const auto& y) {
            return torsion_spring(y[0], y[1], y[2], y[3], rest, k, plastic_set).energy;
          });
    }
  }
}

// At rest and under any twist about the bar, which leaves the references' angles with the bar as
// they were, the weighted spring is the paper's ½ k (φ − φ0)² with k = G J / L0: the model's
// stiffness is k / (q_a0 q_b0), and the weight q_a q_b is q_a0 q_b0 there.
TEST(TorsionSpring, TwistAboutTheBarGivesThePapersSpring) {
  const Vec3 xa(-0.2, 1, 0.1);
  const Vec3 xi(0, 0, 0);
  const Vec3 xj(1, 0, 0);
  const double k = 3.0;
  auto sin2_with_bar = [&](const Vec3& u) {
    return u.cross(xj - xi).squaredNorm() / (u.squaredNorm() * (xj - xi).squaredNorm());
  };
  const Vec3 rest_b(1.3, 0.6, 0.0);
  const double rest_weight = sin2_with_bar(xa - xi) * sin2_with_bar(rest_b - xj);
  const double rest = dihedral_angle(xa, xi, xj, rest_b);
  for (const double twist : {0.0, 0.1, 0.4, -1.2, 2.5}) {
    const Vec3 xb(1.3, 0.6 * std::cos(twist), 0.6 * std::sin(twist));
    const TorsionSpringResult r = torsion_spring(xa, xi, xj, xb, rest, k / rest_weight);
    const double phi = wrap_angle(dihedral_angle(xa, xi, xj, xb) - rest);
    EXPECT_NEAR(std::abs(phi), std::abs(twist), 1e-12);
    EXPECT_NEAR(r.energy, 0.5 * k * phi * phi, 1e-6 * r.energy + 1e-15);  // fast_atan2's error
  }
}

TEST(AxialSpring, ForceWithPlasticSetIsMinusTheEnergyGradient) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec3> x = random_points(rng, 2);
    const AxialSpringResult r = axial_spring(x[0], x[1], 0.8, 50.0, 0.05);
    expect_force_is_minus_gradient(x, {r.force_on_n0, Vec3(-r.force_on_n0)}, [&](const auto& y) {
      return axial_spring(y[0], y[1], 0.8, 50.0, 0.05).energy;
    });
  }
}

TEST(GroundContact, NormalForceIsMinusTheGradientOfThePenaltyEnergy) {
  GroundContact ground;
  ground.enabled = true;
  ground.point = Vec3(0.1, -0.2, 0.3);
  ground.normal = Vec3(0.2, -0.1, 1.0).normalized();
  const double k = 400.0;
  const std::vector<Vec3> x = {Vec3(0.3, 0.1, 0.1)};  // below the plane
  ASSERT_LT((x[0] - ground.point).dot(ground.normal), 0.0);
  const ContactForces f = ground_contact(ground, k, 0.0, 0.0, 1.0, x[0], Vec3::Zero(), x[0], false);
  expect_force_is_minus_gradient(x, {f.normal_elastic}, [&](const auto& y) {
    return ground_contact(ground, k, 0.0, 0.0, 1.0, y[0], Vec3::Zero(), y[0], false).energy;
  });
}

TEST(GroundContact, OnlyEverPushes) {
  GroundContact ground;
  ground.enabled = true;
  // Barely below the plane but leaving it fast: the damper would pull; the clip stops that.
  const ContactForces f = ground_contact(ground, 1e4, 50.0, 10.0, 1.0, Vec3(0, 0, -1e-4),
                                         Vec3(0, 0, 10.0), Vec3::Zero(), false);
  EXPECT_GE((f.normal_elastic + f.normal_damping).dot(ground.normal), 0.0);
  EXPECT_NEAR((f.normal_elastic + f.normal_damping).norm(), 0.0, 1e-12);
}

// A node lifting off (N = 0) with a tangential velocity holds nothing, but is not sliding: when
// it presses again, static friction holds it up to μs N, not μk N.
TEST(GroundContact, LiftingOffLeavesStaticFrictionForTheNextTouch) {
  GroundContact ground;
  ground.enabled = true;
  ground.static_friction = 0.5;
  ground.kinetic_friction = 0.2;
  const double k = 1e4;
  const Vec3 below(0, 0, -1e-4);
  const ContactForces lifting =
      ground_contact(ground, k, 50.0, 10.0, 1.0, below, Vec3(1, 0, 10), Vec3::Zero(), false);
  EXPECT_EQ(lifting.normal_elastic.z() + lifting.normal_damping.z(), 0.0);
  EXPECT_EQ(lifting.friction.norm(), 0.0);
  EXPECT_FALSE(lifting.sliding);
  // Pressed at rest: N = k·1e-4 = 1 N, and the stick spring's pull 0.3 N lies between μk N and
  // μs N, so it sticks.
  const Vec3 anchor(0.3 / k, 0, 0);
  const ContactForces pressed =
      ground_contact(ground, k, 0.0, 0.0, 1.0, below, Vec3::Zero(), anchor, lifting.sliding);
  EXPECT_FALSE(pressed.sliding);
  EXPECT_NEAR(pressed.friction.x(), 0.3, 1e-12);
}

// Straight bars: the angle is π, the direction of bending is undefined. The force must stay
// finite and small near there, and vanish at the straight rest shape.
TEST(BendingSpring, StraightBarsGiveNoNaNAndNoSpike) {
  const double k = 5.0;
  const double pi = std::numbers::pi;
  for (const double offset : {0.0, 1e-14, 1e-10, 1e-6, 1e-3}) {
    const Vec3 xa(-1, 0, 0), xc(0, 0, 0), xb(1, offset, 0);
    for (const double rest : {pi, 2.0}) {
      const BendingSpringResult r = bending_spring(xa, xc, xb, rest, k);
      ASSERT_TRUE(r.force_a.allFinite() && r.force_b.allFinite() && r.force_c.allFinite());
      // |f_b| = |M| / L_b with |M| ≤ k |θ − θ0|: never more than the moment over the arm.
      const double moment_bound = k * std::abs(bend_angle(xa, xc, xb) - rest);
      EXPECT_LE(r.force_b.norm(), moment_bound / 1.0 + 1e-12) << offset;
      if (rest == pi) {
        EXPECT_LE(r.force_b.norm(), k * 2.0 * offset + 1e-12) << offset;  // fades with the kink
      }
    }
  }
}

// A spring whose rest is bent by ψ0 has, on ½ k (ψ0 − ψ)² alone, a cone point at straight (ψ = 0):
// its force jumps from k ψ0 one way to k ψ0 the other as the bars pass through straight, which
// central differences turn into an energy error at each crossing. Within ψ < w = min(ψ0, 0.05)
// the energy is an even quartic instead: the force is still minus the energy's gradient there and
// through straight, fades like ψ, and value and force are continuous where it meets the parabola.
TEST(BendingSpring, BentRestIsSmoothThroughStraight) {
  const double k = 2.0;
  const double pi = std::numbers::pi;
  auto bent = [](double psi) { return Vec3(std::cos(psi), std::sin(psi), 0.0); };
  const Vec3 xa(-1, 0, 0), xc(0, 0, 0);
  for (const double rest_deflection : {0.004, 0.3}) {
    const double rest = pi - rest_deflection;
    const double w = std::min(rest_deflection, 0.05);
    for (const double psi : {0.0, 1e-7, 1e-4, 0.5 * w, 0.999 * w, 1.001 * w, 2.0 * w}) {
      const std::vector<Vec3> x = {xa, xc, bent(psi)};
      const BendingSpringResult r = bending_spring(x[0], x[1], x[2], rest, k);
      ASSERT_TRUE(r.force_b.allFinite());
      if (psi > 1e-5) {  // the finite-difference step must not cross straight in a kink-free test
        expect_force_is_minus_gradient(x, {r.force_a, r.force_c, r.force_b}, [&](const auto& y) {
          return bending_spring(y[0], y[1], y[2], rest, k).energy;
        });
      }
      if (psi < w) {
        // |M| ≤ (3 ψ0 / 2w − 1) k ψ near straight (the quartic's curvature there), not k ψ0.
        EXPECT_LE(r.force_b.norm(), (1.5 * rest_deflection / w) * k * psi + 1e-15) << psi;
      }
    }
    // Through straight itself: the energy is even in ψ and its gradient across is continuous.
    const std::vector<Vec3> straight = {xa, xc, bent(0.0)};
    const BendingSpringResult at_straight = bending_spring(xa, xc, bent(0.0), rest, k);
    expect_force_is_minus_gradient(
        straight, {at_straight.force_a, at_straight.force_c, at_straight.force_b},
        [&](const auto& y) { return bending_spring(y[0], y[1], y[2], rest, k).energy; });
    // Where the quartic meets the parabola, value and force agree to first order in the gap.
    const double gap = 1e-9;
    const BendingSpringResult inside = bending_spring(xa, xc, bent(w - gap), rest, k);
    const BendingSpringResult outside = bending_spring(xa, xc, bent(w + gap), rest, k);
    EXPECT_NEAR(inside.energy, 0.5 * k * (rest_deflection - w) * (rest_deflection - w), 1e-8);
    EXPECT_NEAR(inside.energy, outside.energy, 1e-8);
    EXPECT_NEAR(inside.force_b.norm(), outside.force_b.norm(), 1e-6);
    if (rest_deflection <= 0.05) {  // the full quartic k (ψ² − ψ0²)² / 8ψ0²: k ψ0² / 8 at straight
      EXPECT_NEAR(at_straight.energy, k * rest_deflection * rest_deflection / 8.0, 1e-12);
    }
  }
}

// An axial bar pulled past yield and released, by moving its end: the force plateaus at Ny once
// the extension passes Ny/k, and after unloading to zero force the bar keeps Δmax − Ny/k.
TEST(AxialSpring, PulledPastYieldPlateausAndKeepsAPermanentSet) {
  const double rest_length = 1.0;
  const double k = 1000.0;      // N/m
  const double yield = 50.0;    // N: yields at 0.05 m
  const double stretch = 0.12;  // m, Δmax
  const Vec3 x0 = Vec3::Zero();
  double plastic_set = 0.0;
  for (int i = 0; i <= 120; ++i) {  // load in 1 mm steps
    const double extension = stretch * i / 120.0;
    const AxialSpringResult r =
        axial_spring(x0, Vec3(rest_length + extension, 0, 0), rest_length, k, plastic_set, yield);
    plastic_set = r.plastic_set;
    // The force on n0 pulls it towards n1 (+x) with the bar's tension.
    EXPECT_NEAR(r.force_on_n0.x(), std::min(k * extension, yield), 1e-9) << extension;
  }
  double extension = stretch;
  for (; extension > 0.0; extension -= 0.001) {  // unload until the tension is gone
    const AxialSpringResult r =
        axial_spring(x0, Vec3(rest_length + extension, 0, 0), rest_length, k, plastic_set, yield);
    plastic_set = r.plastic_set;
    if (r.force_on_n0.x() <= 0.0) {
      break;
    }
  }
  EXPECT_NEAR(plastic_set, stretch - yield / k, 1e-12);
  EXPECT_NEAR(extension, stretch - yield / k, 1.5e-3);  // within the unloading increment
}

TEST(Elastoplastic, DissipationIsYieldTimesPlasticFlow) {
  const ElastoplasticResult r = elastoplastic(0.2, 0.0, 1000.0, 50.0);
  EXPECT_NEAR(r.plastic_set, 0.15, 1e-12);
  EXPECT_NEAR(r.dissipated, 50.0 * 0.15, 1e-12);
  EXPECT_NEAR(r.energy, 0.5 * 50.0 * 50.0 / 1000.0, 1e-12);
}

TEST(TimeProfile, StepRampAndSine) {
  TimeProfile step{TimeProfile::Kind::kStep, 0.5};
  EXPECT_EQ(step(0.49), 0.0);
  EXPECT_EQ(step(0.5), 1.0);
  TimeProfile ramp{TimeProfile::Kind::kRamp, 1.0, 3.0};
  EXPECT_EQ(ramp(0.0), 0.0);
  EXPECT_DOUBLE_EQ(ramp(2.5), 0.75);
  EXPECT_EQ(ramp(4.0), 1.0);
  TimeProfile sine{TimeProfile::Kind::kSine, 1.0, 0.0, 2.0, 0.0};
  EXPECT_EQ(sine(0.9), 0.0);
  EXPECT_NEAR(sine(1.125), 1.0, 1e-12);  // a quarter period of 2 Hz after the start
}

TEST(Geometry, FastAtan2MatchesTheLibrary) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> exponent(-12.0, 12.0);
  std::uniform_int_distribution<int> sign(0, 1);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double y = (sign(rng) ? 1 : -1) * std::pow(10.0, exponent(rng));
    const double x = (sign(rng) ? 1 : -1) * std::pow(10.0, exponent(rng));
    const double reference = std::atan2(y, x);
    worst = std::max(worst, std::abs(fast_atan2(y, x) - reference) / std::abs(reference));
  }
  EXPECT_LT(worst, 1e-15);  // a few ulps
  for (const auto& [y, x] : std::vector<std::pair<double, double>>{
           {0.0, 1.0}, {0.0, -1.0}, {1.0, 0.0}, {-1.0, 0.0}, {1.0, 1.0}, {1e-300, -1.0}}) {
    EXPECT_NEAR(fast_atan2(y, x), std::atan2(y, x), 1e-15) << y << " " << x;
  }
}

TEST(Geometry, DihedralAngleAndWrap) {
  // a above the x axis in the x-y plane, b rotated by +30° about the axis i→j = +x.
  const double angle = std::numbers::pi / 6;
  const Vec3 a(0, 1, 0), i(0, 0, 0), j(1, 0, 0), b(1, std::cos(angle), std::sin(angle));
  EXPECT_NEAR(std::abs(dihedral_angle(a, i, j, b)), angle, 1e-12);
  EXPECT_NEAR(wrap_angle(3.5 * std::numbers::pi), -0.5 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(wrap_angle(-0.25), -0.25, 1e-15);
}

}  // namespace
}  // namespace dinam
