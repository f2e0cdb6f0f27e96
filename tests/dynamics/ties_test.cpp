// Ties (`attach`, dynamics/tie_springs.hpp) against closed forms, under every integrator: a
// weight hung on ties of stiffness k sags m g / k at rest and bobs at √(k/m); a bar tied rigidly
// at one end swings as the pendulum, 2π √(L/g), its end held; a tie breaks above its break_force
// and holds below it; tied objects are left out of each other's contact where they are tied; and
// the scene's mistakes are told at their lines.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "dynamics/contact/contact_at_rest.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "stepping/stepper.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

constexpr double kGravity = 9.81;

Model tied_scene(const std::string& integrator, const std::string& rest) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
integrator: {}
gravity: [0, 0, -{}]
ground: {{contact: false}}
{})",
                                                       integrator, kGravity, rest)));
}

struct TiedRun {
  const Model& model;
  TimeStep timestep;
  std::unique_ptr<Stepper> stepper;
  State state;

  TiedRun(const Model& m, double fps, Settling settling, std::optional<double> step = std::nullopt)
      : model(m),
        timestep(choose_timestep(m, step, fps, {})),
        stepper(stepper_kind(m).make_stepper(m, timestep)),
        state(stepper->start(false, settling)) {}
};

// A 10 cm bar of 1 g a node (E A large: it does not stretch) whose two nodes are each tied, at no
// distance, to a pinned beam's nodes by 4 N/m: each node a mass of m = 1 g on its own spring.
std::string weight_on_ties(const std::string& ties, const std::string& scene_keys = "") {
  return fmt::format(R"(duration: 4
fps: 100
{}
objects:
  - name: beam
    mesh: {{polyline: {{points: [[0, 0, 1], [0.1, 0, 1]]}}}}
    role: collider
  - name: weight
    mesh: {{polyline: {{points: [[0, 0, 1], [0.1, 0, 1]]}}}}
    # ρ A L / 2 = 1 g a node: A = 2e-5 m², ρ = 1000 kg/m³.
    material: {{density: 1000, youngs_modulus: 1.0e8, area: 2.0e-5}}
    torsion: false
    attach:
      - {{nodes: {{all: true}}, to: beam, {}}}
)",
                     scene_keys, ties);
}

// The settle (Newton's method on the potential, the ties' energy and stiffness in it) hangs each
// node m g / k = 2.4525 mm below its tie, to its residual (1e-6 of the weight: 1e-6 of the sag).
TEST(Ties, AWeightOnTiesOfGivenStiffnessSagsByItsWeightOverTheirStiffness) {
  for (const std::string integrator : {"central_difference", "implicit", "xpbd"}) {
    SCOPED_TRACE(integrator);
    const Model model =
        tied_scene(integrator, weight_on_ties("stiffness: 4", "settle: {residual: 1.0e-9}"));
    ASSERT_EQ(model.ties.count(), 2);
    ASSERT_NEAR(model.node_mass[2], 1e-3, 1e-12);
    TiedRun run(model, 100.0, Settling::kRun);
    const double sag = 1e-3 * kGravity / 4.0;
    for (Index i = 2; i < 4; ++i) {
      EXPECT_NEAR(1.0 - run.state.x[i].z(), sag, 1e-6 * sag) << i;
    }
  }
}

// From rest at the ties, each node bobs between 0 and 2 m g / k at ω = √(k/m) = 63.2 rad/s:
// it is lowest first at π/ω = 49.7 ms. At steps of 20 µs (ω h = 1.3e-3) every scheme's period
// and amplitude errors are far below 1 % and 2 % (XPBD's and the implicit schemes' damping, a
// share of (ω h)² a step, takes 0.2 % over the half period); a tie of twice or half the
// stiffness is off by 30 %.
TEST(Ties, AWeightOnTiesOfGivenStiffnessBobsAtTheirFrequency) {
  for (const std::string integrator : {"central_difference", "implicit_bdf2", "xpbd"}) {
    SCOPED_TRACE(integrator);
    const Model model = tied_scene(integrator, weight_on_ties("stiffness: 4"));
    TiedRun run(model, 100.0, Settling::kSkip, 2.0e-5);
    double lowest = 1.0;
    double when = 0.0;
    while (run.state.time < 0.08) {
      run.stepper->advance(run.state, 1);
      if (run.state.x[2].z() < lowest) {
        lowest = run.state.x[2].z();
        when = run.state.time;
      }
    }
    const double omega = std::sqrt(4.0 / 1e-3);
    EXPECT_NEAR(when, std::numbers::pi / omega, 0.01 * std::numbers::pi / omega);
    EXPECT_NEAR(1.0 - lowest, 2.0 * 1e-3 * kGravity / 4.0, 0.02 * 2.0 * 1e-3 * kGravity / 4.0);
  }
}

// A 0.5 m bar, its upper node tied rigidly (no stiffness given) where it starts, at a pinned
// beam's node, released 5° from the vertical: its lower node (the bar's mass lumped half at
// each end, the upper one held) swings as the simple pendulum, T = 2π √(L/g) (1.4185 s; 0.05 %
// longer at 5°), and the tie gives under a thousandth of the bar's length.
TEST(Ties, ABarTiedRigidlyAtOneEndSwingsAsThePendulum) {
  const double length = 0.5;
  const double angle = 5.0 * std::numbers::pi / 180.0;
  const std::string scene = fmt::format(R"(duration: 4
fps: 50
objects:
  - name: beam
    mesh: {{polyline: {{points: [[-0.2, 0, 2], [0, 0, 2], [0.2, 0, 2]]}}}}
    role: collider
  - name: bar
    mesh: {{polyline: {{points: [[0, 0, 2], [{}, 0, {}]]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e9, radius: 0.002}}
    torsion: false
    attach:
      - {{nodes: {{indices: [0]}}, to: beam}}
)",
                                        length * std::sin(angle), 2.0 - length * std::cos(angle));
  for (const std::string integrator : {"central_difference", "implicit_bdf2", "xpbd"}) {
    SCOPED_TRACE(integrator);
    const Model model = tied_scene(integrator, scene);
    ASSERT_EQ(model.ties.count(), 1);
    EXPECT_EQ(model.ties.rigid[0], 1);
    TiedRun run(model, 50.0, Settling::kSkip);
    const Index top = 3;
    const Index end = 4;
    double previous_x = run.state.x[end].x();
    std::vector<double> crossings;  // s, where the end passes under the pivot
    double most_give = 0.0;
    while (run.state.time < 3.0) {
      const double t0 = run.state.time;
      run.stepper->advance(run.state, run.timestep.steps_per_frame);
      const double x = run.state.x[end].x();
      if ((previous_x > 0.0) != (x > 0.0)) {
        crossings.push_back(t0 + (run.state.time - t0) * previous_x / (previous_x - x));
      }
      previous_x = x;
      most_give = std::max(most_give, (run.state.x[top] - Vec3(0, 0, 2)).norm());
    }
    ASSERT_GE(crossings.size(), 4U);
    const double period = crossings[3] - crossings[1];
    const double expected =
        2.0 * std::numbers::pi * std::sqrt(length / kGravity) * (1.0 + angle * angle / 16.0);
    EXPECT_NEAR(period, expected, 0.01 * expected);
    EXPECT_LT(most_give, 1e-3 * length);
  }
}

// A short bob (a 1 cm bar, both nodes tied) 0.5 m below a pinned beam's node, 5° from the
// vertical: tied with `swing: true` each node keeps its distance from its point and swings as the
// simple pendulum, crossing under the pivot at T/4; tied as by default, each keeps its offset, and
// the bob stays where it was (within the ties' give).
TEST(Ties, ASwingingTieKeepsItsDistanceAndSwingsWhereTheDefaultHoldsItsPlace) {
  const double length = 0.5;
  const double angle = 5.0 * std::numbers::pi / 180.0;
  const double x = length * std::sin(angle);
  const double z = 2.0 - length * std::cos(angle);
  for (const bool swings : {true, false}) {
    SCOPED_TRACE(swings ? "swing" : "offset");
    const Model model = tied_scene("central_difference", fmt::format(R"(duration: 2
fps: 50
objects:
  - name: beam
    mesh: {{polyline: {{points: [[0, -0.2, 2], [0, 0, 2], [0, 0.2, 2]]}}}}
    role: collider
  - name: bob
    mesh: {{polyline: {{points: [[{}, -0.005, {}], [{}, 0.005, {}]]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e8, radius: 0.002}}
    torsion: false
    attach:
      - {{nodes: {{all: true}}, to: beam, swing: {}}}
)",
                                                                     x, z, x, z, swings));
    TiedRun run(model, 50.0, Settling::kSkip);
    const double quarter = 0.5 * std::numbers::pi * std::sqrt(length / kGravity);
    double farthest = 0.0;
    double crossed = -1.0;
    double previous = run.state.x[3].x();
    while (run.state.time < 0.6) {
      const double t0 = run.state.time;
      run.stepper->advance(run.state, 1);
      const double now = run.state.x[3].x();
      if (crossed < 0.0 && previous > 0.0 && now <= 0.0) {
        crossed = t0 + (run.state.time - t0) * previous / (previous - now);
      }
      previous = now;
      farthest = std::max(farthest, (run.state.x[3] - Vec3(x, -0.005, z)).norm());
    }
    if (swings) {
      EXPECT_NEAR(crossed, quarter, 0.01 * quarter);
    } else {
      EXPECT_LT(crossed, 0.0) << "it swung";
      EXPECT_LT(farthest, 1e-3);
    }
  }
}

// A bar hanging from a tie at its upper node, settled at rest: the tie holds the bar's weight,
// M g. With a break_force 10 % above that it holds; 10 % below, it breaks at the first step and
// the bar falls freely, ½ g t² in 0.3 s (0.44 m).
TEST(Ties, ATieBreaksAboveItsBreakForceAndHoldsBelowIt) {
  const double weight = 2.0 * 1e-3 * kGravity;  // two nodes of 1 g
  for (const std::string integrator : {"central_difference", "implicit", "xpbd"}) {
    SCOPED_TRACE(integrator);
    for (const double share : {1.1, 0.9}) {
      const Model model = tied_scene(integrator, fmt::format(R"(duration: 1
fps: 100
settle: {{}}
objects:
  - name: hook
    mesh: {{polyline: {{points: [[-0.1, 0, 1], [0.1, 0, 1]]}}}}
    role: collider
  - name: bar
    mesh: {{polyline: {{points: [[0, 0, 1], [0, 0, 0.9]]}}}}
    material: {{density: 1000, youngs_modulus: 1.0e8, area: 2.0e-5}}
    torsion: false
    attach:
      - {{nodes: {{indices: [0]}}, to: hook, break_force: {}}}
)",
                                                             share * weight));
      ASSERT_TRUE(model.ties.can_break);
      TiedRun run(model, 100.0, Settling::kRun);
      const double start = run.state.x[3].z();
      const std::int64_t steps = std::llround(0.3 / run.timestep.dt);
      run.stepper->advance(run.state, steps);
      const double fell = start - run.state.x[3].z();
      if (share > 1.0) {
        EXPECT_LT(std::abs(fell), 1e-3) << "held";
      } else {
        const double t = run.state.time;
        // Within one step's fall, g t h: backward Euler's free fall runs g t h / 2 ahead of ½ g t².
        EXPECT_NEAR(fell, 0.5 * kGravity * t * t, kGravity * t * run.timestep.dt + 1e-9) << "broke";
      }
    }
  }
}

// A rope tied to a hook where it touches it, with contact between objects: the pairs at the tie
// (sharing no node, but tied) are left out, so the start overlaps nowhere; the same rope merely
// placed there overlaps the hook, and is refused.
TEST(Ties, TiedPartsAreLeftOutOfTheirContactWhereTheyAreTied) {
  const std::string scene = R"(duration: 1
contact: {objects: true}
objects:
  - name: hook
    mesh: {polyline: {points: [[0, -0.1, 1.5], [0, 0.1, 1.5]], segments: 2}}
    role: collider
    contact: {radius: 0.01}
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1.5], [0, 0, 0.7]], segments: 16}}
    material: {preset: hemp_rope}
)";
  const Model tied =
      tied_scene("central_difference", scene + "    attach: [{nodes: {indices: [0]}, to: hook}]\n");
  EXPECT_FALSE(contact_overlap_at_rest(tied, 0.05).has_value());
  const Model placed = tied_scene("central_difference", scene);
  const std::optional<RestOverlap> overlap = contact_overlap_at_rest(placed, 0.05);
  ASSERT_TRUE(overlap.has_value());
  EXPECT_GE(overlap->pairs, 1);
}

TEST(Ties, MistakesAreToldAtTheirLines) {
  const std::string scene = R"(duration: 1
objects:
  - name: pole
    mesh: {polyline: {points: [[0, 0, 0], [0, 0, 2]]}}
    role: collider
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 4}}
    material: {preset: hemp_rope}
)";
  auto with = [&](const std::string& lines) { tied_scene("central_difference", scene + lines); };
  test::expect_user_error([&] { with("    attach: [{nodes: {indices: [0]}, to: flagpole}]\n"); },
                          13, {"'to: flagpole' names no object", "'pole', 'rope'"});
  test::expect_user_error([&] { with("    attach: [{nodes: {indices: [0]}, to: rope}]\n"); }, 13,
                          {"cannot be tied to itself"});
  test::expect_user_error(
      [&] {
        with("    pinned: {indices: [0]}\n    attach: [{nodes: {indices: [0]}, to: pole}]\n");
      },
      14, {"node 0 of object 'rope' is pinned and tied to 'pole'", "take it out of 'pinned'"});
  test::expect_user_error(
      [&] { with("    attach: [{nodes: {indices: [0]}, to: pole, stiffness: -3}]\n"); }, 13,
      {"stiffness"});
  test::expect_user_error(
      [&] { with("    attach: [{nodes: {box: {min: [5, 5, 5], max: [6, 6, 6]}}, to: pole}]\n"); },
      13, {"select none of its nodes"});
  test::expect_user_error([&] { with("    attach: {nodes: {all: true}, to: pole}\n"); }, 13,
                          {"must be a list"});
}

}  // namespace
}  // namespace dinam
