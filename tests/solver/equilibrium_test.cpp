// Static equilibrium by Newton's method (solver/equilibrium.hpp) and the settling phase that uses
// it (solver/settle.hpp), against closed-form statics: a bar hanging by its own weight, a
// cantilever under its own weight (Euler–Bernoulli), a rope resting on the ground; the same
// equilibrium as relaxation where the path does not matter, the same bits on any thread count,
// and relaxation where the path does matter (friction on a slope, yielding, contact between
// objects), with the reason said.
#include <gtest/gtest.h>

#include <cmath>

#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/relaxation.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "solver/equilibrium.hpp"
#include "solver/settle.hpp"
#include "solver/solver_support.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

constexpr double kGravity = 9.81;

State settled(const Model& model, double dt = 1e-4) {
  State state = make_state(model, false);
  settle_under_gravity(model, dt, {}, state);
  return state;
}

double largest_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, (a[i] - b[i]).norm());
  }
  return largest;
}

// One bar pinned at one end and held out level: Newton's method must swing it down a quarter turn
// (its stiffness across is zero at the start, where it carries no tension), and it hangs straight
// down, stretched by its free end's weight: ΔL = m g / k with m = ρ A L0 / 2 and k = E A / L0.
TEST(Equilibrium, HangingBarSwingsDownAndStretchesByItsWeight) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
ground: {contact: false}
objects:
  - name: bar
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]]}}
    material: {density: 1000, youngs_modulus: 1.0e5, area: 1.0e-4}
    pinned: {indices: [0]}
)"));
  State state = make_state(model, false);
  const EquilibriumOutcome outcome =
      find_equilibrium(model, test::static_forces(), {1e-12, 100, false}, state);
  ASSERT_TRUE(outcome.converged) << outcome.failure;
  const double mass = 1000.0 * 1e-4 * 1.0 / 2.0;
  const double stiffness = 1.0e5 * 1e-4 / 1.0;
  const double stretched = 1.0 + mass * kGravity / stiffness;  // 1.0049 m
  EXPECT_NEAR((state.x[1] - Vec3(0, 0, 2.0 - stretched)).norm(), 0.0, 1e-10);
  EXPECT_LT(outcome.iterations, 40);
}

// A clamped cantilever under its own weight w = ρ A g sags w L⁴ / (8 E I) at the tip. The lumped
// model (bending springs of tributary length, loads lumped on the nodes) errs by O(1/N²). (The
// residual asked is what a steel bar of 2.5 cm allows: its axial force rounds to about
// E A ε / h, 5e-7 of a node's weight.)
double cantilever_sag(int segments) {
  const Model model =
      test::clamped_cantilever(segments, "gravity: [0, 0, -9.81]\nsettle: {residual: 1.0e-5}");
  const State state = settled(model);
  EXPECT_TRUE(state.settled.by_newton);
  EXPECT_EQ(state.settled.steps, 0);  // no relaxation: nothing buckles
  const double reference = 7850.0 * 1e-4 * kGravity / (8.0 * 2.0e11 * 4.0e-8);  // 0.12 mm
  return (1.0 - state.x[segments].z()) / reference;
}

TEST(Equilibrium, CantileverSagsByItsOwnWeightAsEulerBernoulli) {
  const double coarse = std::abs(cantilever_sag(10) - 1.0);
  const double fine = std::abs(cantilever_sag(40) - 1.0);
  // Second order: sixteen times less for four times the bars (a factor above 10 allows for the
  // equilibrium's residual, 1e-5 of a node's weight).
  EXPECT_LT(fine, 5e-3);
  EXPECT_LT(fine, coarse / 10.0);
}

// A rope laid on flat ground sinks into the penalty until each node's weight is carried:
// d = m g / k_ground, node by node (the ends carry half a bar, the others a whole one).
TEST(Equilibrium, RopeOnTheGroundSinksByItsWeightOverTheGroundStiffness) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
settle: {residual: 1.0e-10}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 0], [1, 0, 0]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.005}
)"));
  const State state = settled(model);
  ASSERT_TRUE(state.settled.by_newton) << state.settled.fallback;
  for (Index i = 0; i < model.node_count(); ++i) {
    const double sink = model.node_mass[i] * kGravity / model.ground.node_stiffness[i];
    EXPECT_NEAR(state.x[i].z(), -sink, 1e-9 * sink + 1e-15) << i;
    EXPECT_NEAR(state.x[i].x(), model.node_initial_x[i].x(), 1e-12) << i;
    EXPECT_EQ(state.contact_touching[i], 1) << i;  // resting, anchored where it rests
    EXPECT_NEAR((state.contact_anchor[i] - Vec3(state.x[i].x(), state.x[i].y(), 0)).norm(), 0.0,
                1e-15);
  }
}

// A net hanging from a clamped edge: stable all the way, so Newton's method and relaxation find
// the same equilibrium, to what their residuals leave. (A residual asked must be above what the
// forces' rounding allows: a stiff, light, fine net's axial forces round to 1e-5 of a node's
// weight and more.)
std::string hanging_net(int cells, const std::string& method, double residual) {
  return fmt::format(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
ground: {{contact: false}}
settle: {{residual: {}, method: {}}}
objects:
  - name: net
    mesh:
      grid: {{width: 1.0, height: 1.0, columns: {}, rows: {}, diagonals: none}}
      rotation: [-90, 0, 0]
      translation: [0, 0, 2.0]
    material: {{density: 7850, youngs_modulus: 2.0e7, radius: 0.002}}
    pinned: {{box: {{min: [-2, -1, 1.999], max: [2, 1, 2.001]}}, clamped: true}}
)",
                     residual, method, cells, cells);
}

TEST(Equilibrium, WhereThePathDoesNotMatterNewtonFindsRelaxationsEquilibrium) {
  const Model newton = build_model(test::scene_from_yaml(hanging_net(6, "newton", 1e-7)));
  const Model relax = build_model(test::scene_from_yaml(hanging_net(6, "relax", 1e-7)));
  const double dt = kAutoTimestepSafety * critical_timestep(relax);
  const State by_newton = settled(newton, dt);
  const State by_relaxation = settled(relax, dt);
  ASSERT_TRUE(by_newton.settled.by_newton);
  EXPECT_EQ(by_newton.settled.steps, 0);
  EXPECT_FALSE(by_relaxation.settled.by_newton);
  EXPECT_TRUE(by_relaxation.settled.fallback.empty());  // asked for, not fallen back to
  EXPECT_GT(by_relaxation.settled.steps, 100);
  // 1e-7 of a node's weight (5e-7 N) over the stiffness of the net's softest mode (its sway,
  // about 1 N/m) leaves less than a micrometre.
  EXPECT_LT(largest_distance(by_newton.x, by_relaxation.x), 1e-6);
  EXPECT_GT(largest_distance(by_newton.x, newton.node_initial_x), 1e-3);  // it did sag
}

TEST(Equilibrium, IsTheSameBitForBitOnAnyThreadCount) {
  const Model model = build_model(test::scene_from_yaml(hanging_net(40, "newton", 1e-4)));
  ASSERT_TRUE(worth_sharing(model));
  set_thread_count(1);
  const State one = settled(model);
  set_thread_count(2);
  const State two = settled(model);
  set_thread_count(1);
  ASSERT_TRUE(one.settled.by_newton);
  EXPECT_EQ(one.x, two.x);
  EXPECT_EQ(one.settled.newton_iterations, two.settled.newton_iterations);
}

// Where the equilibrium depends on the way there, relaxation serves and the outcome says why.
TEST(Settle, RelaxesWherePathMattersAndSaysWhy) {
  // A rope resting on a slope is held by friction where it landed.
  const Model slope = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
ground: {normal: [0.2, 0, 1], friction: {static: 0.9, kinetic: 0.8}}
settle: {residual: 1.0e-3, duration: 5}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 0.02], [0, 1, 0.02]], segments: 8}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.005}
)"));
  const State on_slope = settled(slope, kAutoTimestepSafety * critical_timestep(slope));
  EXPECT_FALSE(on_slope.settled.by_newton);
  EXPECT_NE(on_slope.settled.fallback.find("slopes"), std::string::npos)
      << on_slope.settled.fallback;

  // A cantilever whose root yields under its own weight (12 N·m against a yield moment of 10)
  // keeps a plastic set the path decides.
  const Model yielding = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
ground: {contact: false}
damping: {global: 5}
settle: {residual: 1.0e-4, duration: 20}
objects:
  - name: beam
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 10}}
    material: {density: 7850, youngs_modulus: 2.0e9, radius: 0.01, yield: {bending: 10.0}}
    pinned: {indices: [0], clamped: true}
    torsion: false
)"));
  const State bent = settled(yielding, kAutoTimestepSafety * critical_timestep(yielding));
  EXPECT_FALSE(bent.settled.by_newton);
  EXPECT_NE(bent.settled.fallback.find("yield"), std::string::npos) << bent.settled.fallback;
}

}  // namespace
}  // namespace dinam
