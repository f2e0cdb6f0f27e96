// The ground's friction inside an implicit step (dynamics/contact/ground_friction_implicit.hpp) for
// a node that lands within the step: it is held from the iterate after the one it went below the
// plane at, with the cap μs k d of its depth d there, which it keeps for the step; it lets go where
// the step's solution has it above the plane again.
#include "dynamics/contact/ground_friction_implicit.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "model/model.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A bar lying 1 cm above the ground, no gravity: nothing touches at the step's start.
Model bar_above_ground() {
  return build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {friction: {static: 0.5, kinetic: 0.4}}
objects:
  - mesh: {polyline: {points: [[0, 0, 0.01], [0.1, 0, 0.01]], segments: 1}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.001}
)"));
}

// Node 0 at `depth` below the plane (its contact point; m) and `slip` along x from where it
// started, node 1 where it started.
std::vector<Vec3> moved(const Model& model, const std::vector<Vec3>& start, double depth,
                        double slip) {
  std::vector<Vec3> x = start;
  x[0].z() = model.ground.node_radius[0] - depth;
  x[0].x() += slip;
  return x;
}

// The friction force on node 0 at x, N.
Vec3 friction_on_first(const ImplicitFriction& friction, const std::vector<Vec3>& x) {
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  friction.add_forces(x, force);
  return force[0];
}

TEST(ImplicitFriction, ALandingNodeKeepsTheCapItJoinedWithForItsStep) {
  const Model model = bar_above_ground();
  const State state = initial_state(model, 1e-3);
  const std::vector<Vec3>& start = state.x;
  ImplicitFriction friction;
  friction.start_step(model, state);
  EXPECT_TRUE(friction.empty());

  // An iterate puts node 0 1 µm into the plane: it joins, anchored below where it started.
  const double k = model.ground.node_stiffness[0];
  const double joined_depth = 1e-6;
  EXPECT_TRUE(friction.join_new_touches(model, start, moved(model, start, joined_depth, 0.0)));
  // A small slip is held by the stick spring, k per metre; a long one at the cap μs k d.
  const double small = 1e-9;
  EXPECT_NEAR(friction_on_first(friction, moved(model, start, joined_depth, small)).x(), -k * small,
              1e-9 * k * small);
  const double cap = 0.5 * k * joined_depth;
  EXPECT_NEAR(friction_on_first(friction, moved(model, start, joined_depth, 1.0)).x(), -cap,
              1e-12 * cap);

  // The solution has it three times as deep: no new round, and it keeps the cap it joined with
  // (not 3 μs k d) for this step.
  const std::vector<Vec3> deeper = moved(model, start, 3.0 * joined_depth, 1.0);
  EXPECT_FALSE(friction.add_new_touches(model, start, deeper));
  EXPECT_NEAR(friction_on_first(friction, deeper).x(), -cap, 1e-12 * cap);
}

TEST(ImplicitFriction, ALandingNodeThatEndsAboveThePlaneLetsGo) {
  const Model model = bar_above_ground();
  const State state = initial_state(model, 1e-3);
  const std::vector<Vec3>& start = state.x;
  ImplicitFriction friction;
  friction.start_step(model, state);
  EXPECT_TRUE(friction.join_new_touches(model, start, moved(model, start, 1e-6, 0.0)));
  // The solution has it back 1 µm above the plane: the step is solved again without its hold.
  const std::vector<Vec3> above = moved(model, start, -1e-6, 1e-3);
  EXPECT_TRUE(friction.add_new_touches(model, start, above));
  EXPECT_EQ(friction_on_first(friction, above), Vec3::Zero());
  // Nothing more to do at that solution.
  EXPECT_FALSE(friction.add_new_touches(model, start, above));
}

}  // namespace
}  // namespace dinam
