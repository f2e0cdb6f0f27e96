// The implicit integrator's cost estimate (solver/implicit_cost.hpp) rests on the size of its
// Hessian's Cholesky factor, which CHOLMOD's analysis gives: checked against a pattern whose
// factor is known in closed form.
#include "solver/implicit_cost.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace dinam
