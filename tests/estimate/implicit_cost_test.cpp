// The implicit integrator's cost estimate (estimate/implicit_cost.hpp) rests on the size of its
// Hessian's Cholesky factor, which CHOLMOD's analysis gives, and on the counts a step takes, which
// it assumes from how the structure will move: checked against a pattern whose factor is known in
// closed form, and Maxwell's count of bar frameworks whose free motions are known.
#include "estimate/implicit_cost.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A chain of n free nodes hanging from a pinned one, bars only: its stiffness is block
// tridiagonal (3 × 3 blocks), a path, which a fill-reducing order factorises without fill. L then
// holds each diagonal block's lower triangle (6) and one off-diagonal block per bar between free
// nodes (9): 6n + 9(n − 1). Its columns hold, node by node, 6, 5 and 4 entries (3, 2 and 1 at the
// chain's end), and a simplicial factorisation's flops are the sum of their squares.
TEST(ImplicitCost, AChainsFactorHasNoFill) {
  const int n = 10;
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
integrator: implicit
ground: {contact: false}
objects:
  - mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e8, radius: 0.005}
    pinned: {indices: [0]}
    bending_pairs: none
    torsion: false
)"));
  ASSERT_EQ(model.bend_count(), 0);
  const HessianFactorSize size = hessian_factor_size(model);
  EXPECT_EQ(size.unknowns, 3 * n);
  EXPECT_EQ(size.nonzeros, 6 * n + 9 * (n - 1));
  const double flops = (n - 1) * (36 + 25 + 16) + (9 + 4 + 1);
  EXPECT_EQ(size.flops, flops);
}

// A tetrahedron (4 nodes, 6 bars) and a cube of quads (8 nodes, 12 bars), as OBJ files, and a
// model of `objects` (YAML) that may name them.
class ImplicitCostFrameworks : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(folder_.path() / "tetrahedron.obj")
        << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    std::ofstream(folder_.path() / "cube.obj")
        << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  }
  Model model(const std::string& keys, const std::string& objects) const {
    return build_model(test::scene_from_yaml(fmt::format(
        "version: 1\nduration: 1\nintegrator: implicit\n{}objects:\n{}", keys, objects)));
  }
  std::string file_object(const std::string& name, double lift) const {
    return fmt::format(
        "  - mesh: {{file: \"{}\", translation: [0, {}, 1]}}\n"
        "    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.01}}\n",
        (folder_.path() / name).string(), lift);
  }

 private:
  test::TemporaryFolder folder_{"frameworks"};
};

constexpr const char* kPolyline =
    R"(  - mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.01}
)";

// Maxwell's count, 3 n − 6 − b a piece (less its rigid motions only where no pin holds it): a
// tetrahedron's bars hold its shape (12 − 6 − 6 = 0), a cube of quads leaves 24 − 6 − 12 = 6 of
// its 24 motions free (it shears), a free wire of 10 bars 33 − 6 − 10 = 17 of 33, the same wire
// pinned at an end 30 − 10 = 20 of 30. Pieces count alone: the tetrahedron's bars do not hold the
// cube beside it (6 of 36).
TEST_F(ImplicitCostFrameworks, BarsFreeShareIsMaxwellsCount) {
  EXPECT_EQ(bars_free_share(model("", file_object("tetrahedron.obj", 0))), 0.0);
  EXPECT_DOUBLE_EQ(bars_free_share(model("", file_object("cube.obj", 0))), 6.0 / 24.0);
  EXPECT_DOUBLE_EQ(bars_free_share(model("", kPolyline)), 17.0 / 33.0);
  EXPECT_DOUBLE_EQ(
      bars_free_share(model("", std::string(kPolyline) + "    pinned: {indices: [0]}\n")),
      20.0 / 30.0);
  EXPECT_DOUBLE_EQ(
      bars_free_share(model("", file_object("tetrahedron.obj", 0) + file_object("cube.obj", 3))),
      6.0 / 36.0);
}

// A flat sheet is the exception to Maxwell's count: its bars all lie in its plane, and hold none
// of its motions across it to first order. A grid of 100 × 100 triangulated cells, 10 201 nodes
// and 30 200 bars, pinned at two corners, counts 3 · 10 199 − 30 200 = 397 free motions by
// Maxwell (1.3 %: it would hold its shape); flat, its 10 199 free nodes' motions across the plane
// are free, and its bars more than hold the plane's own: a third of its motions. It swings.
TEST_F(ImplicitCostFrameworks, AFlatSheetsMotionsAcrossItsPlaneAreFree) {
  const std::string sheet =
      "  - mesh: {grid: {width: 2, height: 2, columns: 100, rows: 100, diagonals: one}}\n"
      "    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.001}\n";
  const Model pinned = model("", sheet + "    pinned: {indices: [0, 100]}\n");
  ASSERT_EQ(pinned.node_count(), 10201);
  ASSERT_EQ(pinned.bar_count(), 30200);
  EXPECT_DOUBLE_EQ(bars_free_share(pinned), 1.0 / 3.0);
  EXPECT_EQ(expected_motion(pinned), ImplicitMotion::kSwings);
  // Free, its rigid motions aside (3 across the plane, 3 in it): it folds where it lands.
  const Model dropped = model("", sheet);
  EXPECT_DOUBLE_EQ(bars_free_share(dropped), (10201.0 - 3.0) / (3.0 * 10201.0));
  EXPECT_EQ(expected_motion(dropped), ImplicitMotion::kFolds);
}

// The counts a step is assumed to take follow: a tetrahedron dropped holds its shape, a cube of
// quads dropped on the ground folds, the same cube with nothing to land on tumbles, and a wire
// held by a pin swings; they take the fewest, the most (folding and tumbling alike) and between
// in factorisations a step. Only a swinging structure's estimate is taken as it is: a free one's
// may be ten times short.
TEST_F(ImplicitCostFrameworks, ExpectsAShellToHoldItsShapeABoxOfQuadsToFoldAndAPinnedWireToSwing) {
  EXPECT_EQ(expected_motion(model("", file_object("tetrahedron.obj", 0))),
            ImplicitMotion::kHoldsItsShape);
  EXPECT_EQ(expected_motion(model("", file_object("cube.obj", 0))), ImplicitMotion::kFolds);
  EXPECT_EQ(expected_motion(model("ground: {contact: false}\n", file_object("cube.obj", 0))),
            ImplicitMotion::kTumbles);
  EXPECT_EQ(expected_motion(model("", std::string(kPolyline) + "    pinned: {indices: [0]}\n")),
            ImplicitMotion::kSwings);
  const ImplicitStepCounts holds = assumed_step_counts(ImplicitMotion::kHoldsItsShape);
  const ImplicitStepCounts swings = assumed_step_counts(ImplicitMotion::kSwings);
  const ImplicitStepCounts folds = assumed_step_counts(ImplicitMotion::kFolds);
  EXPECT_LT(holds.factorizations, swings.factorizations);
  EXPECT_LT(swings.factorizations, folds.factorizations);
  EXPECT_LT(holds.iterations, folds.iterations);
  // A structure that holds its shape but rocks where it lands lies between one that lies still
  // and one that folds.
  const ImplicitStepCounts rocks = assumed_step_counts(ImplicitMotion::kRocks);
  EXPECT_LT(holds.solve_iterations, rocks.solve_iterations);
  EXPECT_LT(holds.factorizations, rocks.factorizations);
  EXPECT_LT(rocks.factorizations, folds.factorizations);
  EXPECT_EQ(estimate_margin(ImplicitMotion::kSwings), 1.0);
  for (const ImplicitMotion free : {ImplicitMotion::kHoldsItsShape, ImplicitMotion::kRocks,
                                    ImplicitMotion::kFolds, ImplicitMotion::kTumbles}) {
    EXPECT_EQ(estimate_margin(free), 10.0);
  }
}

}  // namespace
}  // namespace dinam
