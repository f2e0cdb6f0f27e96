#include "dynamics/axial_spring.hpp"

#include <gtest/gtest.h>

#include <random>

#include "tolerances.hpp"

namespace dinam {
namespace {

// The force on each node must be minus the gradient of the spring energy. Checked by central
// differences on random stretched and compressed configurations.
TEST(AxialSpring, ForceIsMinusTheEnergyGradient) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const double h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 x0(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 x1(coordinate(rng), coordinate(rng), coordinate(rng));
    const double rest_length = 0.5 + 0.5 * (coordinate(rng) + 1.0);  // 0.5 to 1.5 m
    const double k = 250.0;
    const AxialSpringResult r = axial_spring(x0, x1, rest_length, k);
    for (int c = 0; c < 3; ++c) {
      const Vec3 dx = h * Vec3::Unit(c);
      const double dE0 = (axial_spring(Vec3(x0 + dx), x1, rest_length, k).energy -
                          axial_spring(Vec3(x0 - dx), x1, rest_length, k).energy) /
                         (2 * h);
      const double dE1 = (axial_spring(x0, Vec3(x1 + dx), rest_length, k).energy -
                          axial_spring(x0, Vec3(x1 - dx), rest_length, k).energy) /
                         (2 * h);
      const double scale = std::max(1.0, r.force_on_n0.norm());
      EXPECT_NEAR(r.force_on_n0[c], -dE0, test::kGradientRelative * scale);
      EXPECT_NEAR(-r.force_on_n0[c], -dE1, test::kGradientRelative * scale);
    }
  }
}

// Hooke's law: a bar stretched by Δl pulls its ends together with k Δl along the bar.
TEST(AxialSpring, StretchedBarPullsWithStiffnessTimesExtension) {
  const AxialSpringResult r = axial_spring(Vec3(0, 0, 0), Vec3(0, 1.1, 0), 1.0, 200.0);
  EXPECT_NEAR(r.force_on_n0.y(), 200.0 * 0.1, 1e-12);  // towards n1
  EXPECT_NEAR(r.force_on_n0.x(), 0.0, 1e-15);
  EXPECT_NEAR(r.energy, 0.5 * 200.0 * 0.01, 1e-12);
  const AxialSpringResult c = axial_spring(Vec3(0, 0, 0), Vec3(0, 0.9, 0), 1.0, 200.0);
  EXPECT_NEAR(c.force_on_n0.y(), -200.0 * 0.1, 1e-12);  // compressed: pushes n0 away
}

TEST(AxialSpring, ZeroLengthGivesNoForceAndNoNaN) {
  const AxialSpringResult r = axial_spring(Vec3(1, 2, 3), Vec3(1, 2, 3), 1.0, 200.0);
  EXPECT_TRUE(r.force_on_n0.allFinite());
  EXPECT_EQ(r.force_on_n0, Vec3::Zero());
}

}  // namespace
}  // namespace dinam
