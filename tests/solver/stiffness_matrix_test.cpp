// The assembled stiffness: an assembly into the pattern kept from the last one gives the same
// matrix, bit for bit, as one built afresh from the elements' triplets.
#include "solver/stiffness_matrix.hpp"

#include <gtest/gtest.h>

#include <random>

#include "model/model.hpp"
#include "solver_support.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A wire net (axial, bending and torsion springs) lying on the ground, moved at random between
// the assemblies so that every spring's matrix changes and nodes meet and leave the ground.
TEST(StiffnessAssembly, IntoTheKeptPatternIsTheSameAsAfresh) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - mesh: {grid: {width: 0.5, height: 0.5, columns: 8, rows: 8}, translation: [0, 0, 0.002]}
    material: {density: 1000, youngs_modulus: 1.0e8, radius: 0.002}
    style: wire
    pinned: {indices: [0]}
)"));
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
