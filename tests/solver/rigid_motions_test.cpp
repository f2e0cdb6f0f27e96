// The rigid motions a model's pins leave (solver/rigid_motions.hpp): six for a free body, three
// turns about a single pin, one turn about the line of a hinge's two pins, none for a body held
// at three points or a straight rope on its two ends (its turn about its line moves no node); a
// translation and a turn hold their whole norm in them, a bending shape almost none.
#include <gtest/gtest.h>

#include <string>

#include "dynamics/free_dofs.hpp"
#include "model/model.hpp"
#include "solver/rigid_motions.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A square of 1 m in the z = 1 plane, of four bars and a diagonal, pinned at `pins`.
Model square(const std::string& pins) {
  return build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {contact: false}
objects:
  - name: square
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1], [0, 0, 1], [1, 1, 1]]}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.01}
)" + pins));
}

RigidMotions motions_of(const Model& model) {
  return RigidMotions(model, model.node_initial_x, free_dofs(model));
}

TEST(RigidMotions, PinsLeaveSixThreeOneOrNone) {
  EXPECT_EQ(motions_of(square("")).count(), 6);
  EXPECT_EQ(motions_of(square("    pinned: {indices: [0]}\n")).count(), 3);
  EXPECT_EQ(motions_of(square("    pinned: {indices: [0, 1]}\n")).count(), 1);
  EXPECT_EQ(motions_of(square("    pinned: {indices: [0, 1, 2]}\n")).count(), 0);
  // A straight rope held at both ends: its turn about its own line moves none of its nodes.
  const Model rope = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
ground: {contact: false}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.01}
    pinned: {indices: [0, 10]}
)"));
  EXPECT_EQ(motions_of(rope).count(), 0);
}

TEST(RigidMotions, ShareOfATurnASlideAndABend) {
  const Model model = square("    pinned: {indices: [0, 1]}\n");  // a hinge along x at y = 0
  const FreeDofs dofs = free_dofs(model);
  const RigidMotions motions(model, model.node_initial_x, dofs);
  // The turn about the hinge: nodes at y = 1 move along z by 1 (θ = 1 rad, linearised).
  Eigen::VectorXd turn = Eigen::VectorXd::Zero(dofs.count);
  // A slide along x, which the hinge forbids, and a bend: one free node lifted, the other not.
  Eigen::VectorXd slide = Eigen::VectorXd::Zero(dofs.count);
  Eigen::VectorXd bend = Eigen::VectorXd::Zero(dofs.count);
  bool first = true;
  for (Index i = 0; i < model.node_count(); ++i) {
    const Index dof = dofs.first_dof[i];
    if (dof < 0) {
      continue;
    }
    turn[dof + 2] = model.node_initial_x[i].y();
    slide[dof] = 1.0;
    bend[dof + 2] = (first ? 1.0 : -1.0) / model.node_mass[i];
    first = false;
  }
  EXPECT_NEAR(motions.rigid_share(turn), 1.0, 1e-12);
  EXPECT_NEAR(motions.rigid_share(slide), 0.0, 1e-12);
  // The two free nodes are (1, 1) and (0, 1), the turn lifts both alike: lifting one and lowering
  // the other by the same momentum is orthogonal to it in M, a twist no rigid motion makes.
  EXPECT_NEAR(motions.rigid_share(bend), 0.0, 1e-12);
}

}  // namespace
}  // namespace dinam
