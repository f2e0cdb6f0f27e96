// Contact pairs overlapping at rest (dynamics/contact/contact_at_rest.hpp), on a square grid whose
// geometry gives the answer in closed form.
#include "dynamics/contact/contact_at_rest.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A flat 10 × 10 grid of 0.1 m squares in contact with itself, every primitive of radius r.
Model self_touching_grid(double radius) {
  return build_model(test::scene_from_yaml(R"(
version: 1
name: grid
duration: 0.1
fps: 20
contact: {self: true}
objects:
  - name: cloth
    mesh:
      grid: {width: 1, height: 1, columns: 10, rows: 10}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.001}
    contact: {radius: )" + fmt::format("{:.17g}", radius) +
                                           "}\n"));
}

// Pairs that share a node or are joined by a bar never touch; the nearest others on a square
// grid are a node and the corner of a square diagonally next to it, h√2 apart (h = 0.1 m). So a
// radius r overlaps at rest exactly when 2r (less the 5 % tolerance) exceeds h√2.
TEST(ContactAtRest, ASquareGridOverlapsOnceTwoRadiiPassTheDiagonalOfASquare) {
  constexpr double kSpacing = 0.1;
  constexpr double kTolerance = 0.05;
  const double threshold = kSpacing * std::numbers::sqrt2 / (2.0 * (1.0 - kTolerance));
  EXPECT_FALSE(contact_overlap_at_rest(self_touching_grid(0.99 * threshold), kTolerance));
  const std::optional<RestOverlap> overlap =
      contact_overlap_at_rest(self_touching_grid(1.01 * threshold), kTolerance);
  ASSERT_TRUE(overlap);
  EXPECT_NEAR(overlap->distance, kSpacing * std::numbers::sqrt2, 1e-12);
  EXPECT_NEAR(overlap->reach, 2.0 * 1.01 * threshold, 1e-12);
  EXPECT_EQ(overlap->object_a, 0);
  EXPECT_EQ(overlap->object_b, 0);
  EXPECT_GT(overlap->pairs, 0);
}

// Contact off, nothing to judge.
TEST(ContactAtRest, NoContactNoOverlap) {
  const Model model = build_model(test::scene_from_yaml(R"(
version: 1
name: grid
duration: 0.1
fps: 20
objects:
  - name: cloth
    mesh:
      grid: {width: 1, height: 1, columns: 10, rows: 10}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.5}
)"));
  EXPECT_FALSE(contact_overlap_at_rest(model, 0.05));
}

}  // namespace
}  // namespace dinam
