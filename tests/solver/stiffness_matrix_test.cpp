// The assembled stiffness: an assembly into the pattern kept from the last one gives the same
// matrix, bit for bit, as one built afresh from the elements' triplets; and the same on any number
// of threads (the element matrices are computed on the team, added in spring order).
#include "solver/stiffness_matrix.hpp"

#include <gtest/gtest.h>

#include <random>

#include "core/thread_team.hpp"
#include "dynamics/stiffness.hpp"
#include "model/model.hpp"
#include "solver_support.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A wire net of 8 × 8 cells (axial, bending and torsion springs) 2 mm above the ground, pinned at
// a corner.
Model wire_net() {
  return build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - mesh: {grid: {width: 0.5, height: 0.5, columns: 8, rows: 8}, translation: [0, 0, 0.002]}
    material: {density: 1000, youngs_modulus: 1.0e8, radius: 0.002}
    style: wire
    pinned: {indices: [0]}
)"));
}

// The wire net (144 bars, and more bending and torsion springs: each kind more than
// kMinParallelStiffness), moved at random partly into the ground, assembled on 1 and on 3 threads.
TEST(StiffnessAssembly, IsTheSameBitForBitOnAnyThreadCount) {
  const Model model = wire_net();
  ASSERT_GE(model.torsion_count(), kMinParallelStiffness);
  ASSERT_GE(model.bend_count(), kMinParallelStiffness);
  ASSERT_GE(model.bar_count(), kMinParallelStiffness);
  State state = make_state(model, false);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> shift(-0.01, 0.01);
  for (Vec3& x : state.x) {
    x += Vec3(shift(random), shift(random), shift(random));
  }
  const FreeDofs dofs = free_dofs(model);
  for (const Definiteness definiteness : {Definiteness::kExact, Definiteness::kProjected}) {
    set_thread_count(1);
    StiffnessAssembly one;
    const Eigen::MatrixXd alone(
        one.assemble(model, state, test::static_forces(), dofs, definiteness));
    set_thread_count(3);
    StiffnessAssembly three;
    const Eigen::MatrixXd shared(
        three.assemble(model, state, test::static_forces(), dofs, definiteness));
    set_thread_count(1);
    ASSERT_GT(alone.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(alone, shared);  // every entry, bit for bit
  }
}

// The wire net, moved at random between the assemblies so that every spring's matrix changes and
// nodes meet and leave the ground.
TEST(StiffnessAssembly, IntoTheKeptPatternIsTheSameAsAfresh) {
  const Model model = wire_net();
  ASSERT_GT(model.torsion_count(), 0);
  ASSERT_GT(model.bend_count(), 0);
  State state = make_state(model, false);
  const FreeDofs dofs = free_dofs(model);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.004, 0.004);
  for (const Definiteness definiteness : {Definiteness::kExact, Definiteness::kProjected}) {
    StiffnessAssembly kept;
    kept.assemble(model, state, test::static_forces(), dofs, definiteness);
    for (int round = 0; round < 3; ++round) {
      for (Vec3& x : state.x) {
        x += Vec3(shift(random), shift(random), shift(random));
      }
      const SparseMatrix& reused =
          kept.assemble(model, state, test::static_forces(), dofs, definiteness);
      StiffnessAssembly fresh;
      const SparseMatrix& built =
          fresh.assemble(model, state, test::static_forces(), dofs, definiteness);
      ASSERT_EQ(reused.nonZeros(), built.nonZeros());
      EXPECT_EQ(Eigen::MatrixXd(reused), Eigen::MatrixXd(built)) << "round " << round;
    }
  }
  // Some nodes are below the ground at the end, so its stiffness was among the blocks.
  int below = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    below += model.ground.clearance(i, state.x[i]) < 0.0 ? 1 : 0;
  }
  EXPECT_GT(below, 0);
}

}  // namespace
}  // namespace dinam
