// Contact between objects and within one (dynamics/contact/object_contact.hpp): the closest-point
// kernels and the grid against brute force, then the contact law against closed forms and
// conservation laws, and thrown wires that must not pass through.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>

#include "core/closest_points.hpp"
#include "dynamics/contact/contact_grid.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/restitution.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

Vec3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  return {coordinate(rng), coordinate(rng), coordinate(rng)};
}

// The closest points of two segments against the least distance over 401 × 401 samples of each:
// never farther than the samples' best, and within a sample spacing of it.
TEST(ContactGeometry, SegmentClosestPointsMatchBruteForce) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 p0 = random_point(rng);
    Vec3 p1 = random_point(rng);
    const Vec3 q0 = random_point(rng);
    Vec3 q1 = random_point(rng);
    if (trial % 4 == 1) {
      q1 = q0 + 0.7 * (p1 - p0);  // parallel
    } else if (trial % 4 == 2) {
      p1 = p0;  // a point against a segment
    } else if (trial % 4 == 3) {
      q1 = q0 + (p1 - p0);  // parallel and overlapping in their span
    }
    const SegmentPair closest = closest_points_of_segments(p0, p1, q0, q1);
    ASSERT_GE(closest.s, 0.0);
    ASSERT_LE(closest.s, 1.0);
    ASSERT_GE(closest.t, 0.0);
    ASSERT_LE(closest.t, 1.0);
    const double distance = ((p0 + closest.s * (p1 - p0)) - (q0 + closest.t * (q1 - q0))).norm();
    double sampled = 1e9;
    constexpr int kSamples = 400;
    for (int i = 0; i <= kSamples; ++i) {
      for (int j = 0; j <= kSamples; ++j) {
        const Vec3 p = p0 + (static_cast<double>(i) / kSamples) * (p1 - p0);
        const Vec3 q = q0 + (static_cast<double>(j) / kSamples) * (q1 - q0);
        sampled = std::min(sampled, (p - q).norm());
      }
    }
    EXPECT_LE(distance, sampled + 1e-12) << trial;
    EXPECT_GE(distance, sampled - ((p1 - p0).norm() + (q1 - q0).norm()) / kSamples) << trial;
  }
}

// The closest point of a triangle against 300 × 300 barycentric samples, points in front of,
// beside and behind it, and a triangle of zero area.
TEST(ContactGeometry, TriangleClosestPointMatchesBruteForce) {
  std::mt19937 rng(22);
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 a = random_point(rng);
    const Vec3 b = random_point(rng);
    Vec3 c = random_point(rng);
    if (trial % 10 == 9) {
      c = a + 0.3 * (b - a);  // degenerate
    }
    const Vec3 p = 1.5 * random_point(rng);
    const std::array<double, 3> w = closest_point_of_triangle(p, a, b, c);
    EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-12);
    EXPECT_GE(std::min({w[0], w[1], w[2]}), -1e-12);
    const double distance = (p - (w[0] * a + w[1] * b + w[2] * c)).norm();
    double sampled = 1e9;
    constexpr int kSamples = 300;
    for (int i = 0; i <= kSamples; ++i) {
      for (int j = 0; i + j <= kSamples; ++j) {
        const double u = static_cast<double>(i) / kSamples;
        const double v = static_cast<double>(j) / kSamples;
        sampled = std::min(sampled, (p - ((1 - u - v) * a + u * b + v * c)).norm());
      }
    }
    const double spacing = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / kSamples;
    EXPECT_LE(distance, sampled + 1e-12) << trial;
    EXPECT_GE(distance, sampled - 2 * spacing) << trial;
  }
}

// Every box that overlaps a query is visited once, and no other; boxes not filed are never
// visited. Boxes of very different sizes, clustered so that cells hold many: most narrow, one in
// twenty wide (filed in every cell it covers), one in a hundred wider still (kept aside).
TEST(ContactGrid, VisitsExactlyTheOverlappingBoxesOnce) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> size(0.001, 0.2);
  std::vector<Box> boxes;
  std::vector<std::uint8_t> use;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 centre = (i % 3 == 0 ? 0.1 : 1.0) * random_point(rng);
    const double scale = i % 100 == 1 ? 12.0 : i % 20 == 2 ? 3.0 : 1.0;
    const Vec3 half = scale * Vec3(size(rng), size(rng), size(rng));
    boxes.push_back({centre - 0.5 * half, centre + 0.5 * half});
    use.push_back(i % 7 == 0 ? 0 : 1);
  }
  ContactGrid grid;
  grid.build(boxes, use, 0.0);
  for (int q = 0; q < 400; ++q) {
    const Box& query = boxes[static_cast<std::size_t>(q)];
    std::multiset<Index> visited;
    grid.visit_overlapping(query, [&](Index id) { visited.insert(id); });
    std::multiset<Index> expected;
    for (Index id = 0; id < static_cast<Index>(boxes.size()); ++id) {
      if (use[id] != 0 && boxes[id].overlaps(query)) {
        expected.insert(id);
      }
    }
    EXPECT_EQ(visited, expected) << q;
  }
}

constexpr double kG = 9.81;

// A scene of `objects` (YAML list items, indented as under `objects:`) with contact between
// objects, without gravity unless given.
Model contact_scene(const std::string& objects, const std::string& contact,
                    const std::string& extra = "gravity: [0, 0, 0]\n") {
  return build_model(test::scene_from_yaml(fmt::format(
      "version: 1\nduration: 1\n{}contact: {}\nobjects:\n{}", extra, contact, objects)));
}

// A pinned straight wire along y through the origin, 1 m long in 10 bars, and a free one of
// `segments` bars and length `length` centred at `centre`, turned by `degrees` about z from x,
// moving at `velocity`. Both of 5 mm radius.
std::string wire_at_wire(double degrees, const Vec3& centre, const Vec3& velocity, int segments = 6,
                         double length = 0.6) {
  const double phi = degrees * std::numbers::pi / 180.0;
  const Vec3 half = 0.5 * length * Vec3(std::cos(phi), std::sin(phi), 0.0);
  const Vec3 a = centre - half;
  const Vec3 b = centre + half;
  return fmt::format(R"(  - name: fixed
    mesh: {{polyline: {{points: [[0, -0.5, 0], [0, 0.5, 0]], segments: 10}}}}
    material: {{density: 7850, youngs_modulus: 2.0e9, radius: 0.005}}
    pinned: {{all: true}}
  - name: thrown
    mesh: {{polyline: {{points: [[{}, {}, {}], [{}, {}, {}]], segments: {}}}}}
    material: {{density: 7850, youngs_modulus: 2.0e9, radius: 0.005}}
    initial_velocity: [{}, {}, {}]
)",
                     a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), segments, velocity.x(), velocity.y(),
                     velocity.z());
}

Vec3 sum_of(const std::vector<Vec3>& forces) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : forces) {
    sum += f;
  }
  return sum;
}

// Momentum: two free wires pressed into each other, one sliding across the other, push with
// forces that sum to zero (each pair's forces are equal and opposite), and push them apart.
TEST(ObjectContact, ForcesConserveMomentum) {
  const std::string objects = R"(  - name: a
    mesh: {polyline: {points: [[-0.3, 0.05, 0], [0.3, -0.05, 0]], segments: 3}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.01}
    initial_velocity: [0.2, 0.5, 1]
  - name: b
    mesh: {polyline: {points: [[0.02, -0.3, 0.012], [-0.02, 0.3, 0.015]], segments: 4}}
    material: {density: 3000, youngs_modulus: 1.0e7, radius: 0.008}
    initial_velocity: [0, -0.4, -1]
)";
  const Model model = contact_scene(objects, "{objects: true, damping_ratio: 0.4}");
  ForceSwitches only_contact;
  only_contact.axial_springs = only_contact.bending = only_contact.torsion = false;
  only_contact.gravity = only_contact.fields = only_contact.wind = only_contact.ground = false;
  only_contact.axial_dampers = only_contact.global_damping = false;
  State state = initial_state(model, 1e-5, only_contact);
  compute_forces(model, only_contact, state, false);
  const Vec3 total = sum_of(state.force);
  Vec3 on_a = Vec3::Zero();
  for (Index i = 0; i < model.node_count(); ++i) {
    on_a += model.node_object[i] == 0 ? state.force[i] : Vec3::Zero();
  }
  ASSERT_GT(on_a.norm(), 1.0);                   // N: they do touch
  EXPECT_LT(total.norm(), 1e-12 * on_a.norm());  // and the forces cancel
  EXPECT_LT(on_a.z(), 0.0);                      // wire a, below, is pushed down
}

// A short bar thrown at 3 m/s onto a pinned 2 m cloth comes to rest on it at the thickness: its
// nodes' height is r_bar + r_cloth − m_node g / k, each node held by one contact of the automatic
// stiffness's soft layer, k = ω_c² m_node / 16 (the cloth is pinned). Once inside a triangle (one
// cell); once with a node on a vertex where six triangles and six bars meet and the other on an
// edge (2 × 2 cells): still one contact each, or the bar would sink by less. The global damping
// brings it to rest.
TEST(ObjectContact, NodeThrownOntoAPinnedClothRestsAtTheThickness) {
  for (const auto& [cells, pebble] :
       {std::pair{1, std::string("[[1.5, 0.3, 0.05], [1.51, 0.3, 0.05]]")},
        std::pair{2, std::string("[[1.0, 1.0, 0.05], [1.01, 1.0, 0.05]]")}}) {
    const Model model = contact_scene(fmt::format(R"(  - name: cloth
    mesh: {{grid: {{width: 2, height: 2, columns: {0}, rows: {0}, diagonals: one}}}}
    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.003}}
    pinned: {{all: true}}
  - name: pebble
    mesh: {{polyline: {{points: {1}}}}}
    material: {{density: 8000, youngs_modulus: 1.0e8, radius: 0.002}}
    initial_velocity: [0, 0, -3]
)",
                                                  cells, pebble),
                                      "{objects: true}", "damping: {global: 8}\n");
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    State state = initial_state(model, dt);
    const Index node = model.node_count() - 1;
    double lowest = 1.0;
    while (state.time < 3.0) {
      step(model, dt, {}, state);
      lowest = std::min(lowest, state.x[node].z());
    }
    // m g / k, k the soft layer's near the surface: a sixteenth of the stiff ω_c² m.
    const double sag = 16.0 * kG / model.contact.omega_squared;
    std::printf("rests %.4g m deep (sag %.3g m), pressed in to %.4g m\n", 0.005 - state.x[node].z(),
                sag, 0.005 - lowest);
    const double expected = 0.003 + 0.002 - sag;
    EXPECT_GT(lowest, 0.0) << cells;                  // it never went through
    EXPECT_LT(lowest, expected - 10 * sag) << cells;  // the impact did press in
    EXPECT_NEAR(state.x[node].z(), expected, 1e-3 * sag) << cells;
    EXPECT_NEAR(state.x[node - 1].z(), expected, 1e-3 * sag) << cells;
  }
}

constexpr const char* kNoGravityNoGround = "gravity: [0, 0, 0]\nground: {contact: false}\n";

// Beyond the speed envelope: a node that crosses a triangle's middle within one step (at
// 1.1 × its reach a step, starting 1.05 reaches above it) is pushed back to the side it came
// from, and bounces, instead of on through the cloth as the nearer side would have it.
TEST(ObjectContact, ANodeThatCrossesATrianglesMiddleInOneStepIsPushedBackToItsSide) {
  const Model model = contact_scene(R"(  - name: cloth
    mesh: {grid: {width: 0.2, height: 0.2, columns: 1, rows: 1, diagonals: one}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.003}
    pinned: {all: true}
  - name: pebble
    mesh: {polyline: {points: [[0.12, 0.05, 0.05], [0.13, 0.05, 0.05]]}}
    material: {density: 8000, youngs_modulus: 1.0e8, radius: 0.002}
)",
                                    "{objects: true}", kNoGravityNoGround);
  const double reach = 0.003 + 0.002;
  const double dt = kAutoTimestepSafety * critical_timestep(model);
  State state = initial_state(model, dt);
  const ModelObject& pebble = model.objects[1];
  for (Index i = pebble.first_node; i < pebble.first_node + pebble.node_count; ++i) {
    state.x[i].z() = 1.05 * reach;
    state.velocity[i] = Vec3(0, 0, -1.1 * reach / dt);
  }
  double lowest = 1.0;
  while (state.time < 0.01) {
    step(model, dt, {}, state);
    lowest = std::min(lowest, state.x[pebble.first_node].z());
  }
  EXPECT_LT(lowest, 0.0);                            // it did cross the middle
  EXPECT_GT(state.x[pebble.first_node].z(), reach);  // and went back the way it came
  EXPECT_GT(state.velocity[pebble.first_node].z(), 0.0);
}

// The least distance between the axes of the two wires' bars, and the side of the fixed wire
// the thrown one's middle node is on.
struct WireWatch {
  double closest = 1e9;  // m
  double lowest_middle = 1e9;
};

void watch_wires(const Model& model, const State& state, WireWatch& watch) {
  const ModelObject& fixed = model.objects[0];
  const ModelObject& thrown = model.objects[1];
  for (Index a = fixed.first_bar; a < fixed.first_bar + fixed.bar_count; ++a) {
    for (Index b = thrown.first_bar; b < thrown.first_bar + thrown.bar_count; ++b) {
      const Vec3& p0 = state.x[model.bar_nodes[2 * a]];
      const Vec3& p1 = state.x[model.bar_nodes[2 * a + 1]];
      const Vec3& q0 = state.x[model.bar_nodes[2 * b]];
      const Vec3& q1 = state.x[model.bar_nodes[2 * b + 1]];
      const SegmentPair c = closest_points_of_segments(p0, p1, q0, q1);
      watch.closest =
          std::min(watch.closest, ((p0 + c.s * (p1 - p0)) - (q0 + c.t * (q1 - q0))).norm());
    }
  }
  const Index middle = thrown.first_node + thrown.node_count / 2;
  watch.lowest_middle = std::min(watch.lowest_middle, state.x[middle].z());
}

// The envelope: relative speed × Δt below the smaller radius. A wire thrown at 10 m/s at a pinned
// wire, crossing it at 90°, 45° and 15°, bounces off: the wires' axes never come nearer than a
// radius and its middle stays above. Δt is the automatic step (here 10 m/s × Δt ≈ 0.1 mm against
// 5 mm radii).
TEST(ObjectContact, WireThrownAtAWireNeverPassesThrough) {
  for (const double degrees : {90.0, 45.0, 15.0}) {
    const Model model =
        contact_scene(wire_at_wire(degrees, Vec3(0, 0, 0.03), Vec3(0, 0, -10)), "{objects: true}");
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    ASSERT_LT(10.0 * dt, 0.005);
    State state = initial_state(model, dt);
    WireWatch watch;
    while (state.time < 0.01) {
      step(model, dt, {}, state);
      watch_wires(model, state, watch);
    }
    EXPECT_GT(watch.closest, 0.005) << degrees;  // the axes stayed a radius apart at least
    EXPECT_LT(watch.closest, 0.01) << degrees;   // and they did touch
    EXPECT_GT(watch.lowest_middle, 0.0) << degrees;
    std::printf(
        "wire at %g°: axes at least %.4f m apart (radii 0.005 each), 10 m/s × Δt = %.2g m\n",
        degrees, watch.closest, 10.0 * dt);
    const Index middle = model.objects[1].first_node + model.objects[1].node_count / 2;
    EXPECT_GT(state.velocity[middle].z(), 0.0) << degrees;  // on its way back up
  }
}

// A wire thrown at 10 m/s onto a pinned cloth (10 × 10 cells of 0.1 m) at 90°, 60° and 30° to
// its plane: no node of the wire ever reaches the cloth's plane.
TEST(ObjectContact, WireThrownAtAPinnedClothNeverPassesThrough) {
  for (const double degrees : {90.0, 60.0, 30.0}) {
    const double angle = degrees * std::numbers::pi / 180.0;
    const Vec3 velocity = 10.0 * Vec3(std::cos(angle), 0.0, -std::sin(angle));
    const Model model = contact_scene(fmt::format(R"(  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: 10, rows: 10, diagonals: one}}}}
    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.003}}
    pinned: {{all: true}}
  - name: thrown
    mesh: {{polyline: {{points: [[0.33, 0.27, 0.03], [0.41, 0.55, 0.05]], segments: 5}}}}
    material: {{density: 7850, youngs_modulus: 2.0e9, radius: 0.004}}
    initial_velocity: [{}, 0, {}]
)",
                                                  velocity.x(), velocity.z()),
                                      "{objects: true}");
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    State state = initial_state(model, dt);
    double lowest = 1.0;
    const ModelObject& thrown = model.objects[1];
    while (state.time < 0.02) {
      step(model, dt, {}, state);
      for (Index i = thrown.first_node; i < thrown.first_node + thrown.node_count; ++i) {
        lowest = std::min(lowest, state.x[i].z());
      }
    }
    EXPECT_GT(lowest, 0.0) << degrees;
    EXPECT_LT(lowest, 0.007) << degrees;  // it did touch (0.003 + 0.004)
  }
}

// Without contact damping or friction a collision gives back the energy it took: a wire thrown
// at a pinned one keeps its energy balance through the impact to the integrator's error (at a
// fifth of the automatic step, as for the ground: an impact at the automatic step is resolved
// to a few percent).
TEST(ObjectContact, ElasticCollisionKeepsTheEnergy) {
  const Model model =
      contact_scene(wire_at_wire(70.0, Vec3(0.05, 0, 0.02), Vec3(0, 0, -2)),
                    "{objects: true, damping_ratio: 0, friction: {static: 0, kinetic: 0}}");
  const double dt = 0.2 * kAutoTimestepSafety * critical_timestep(model);
  State state = initial_state(model, dt, {}, true);
  const double start = state.energy_workspace.last.total;
  const double kinetic = state.energy_workspace.last.kinetic;
  double largest_drift = 0.0;
  double largest_contact = 0.0;
  while (state.time < 0.03) {
    step(model, dt, {}, state);
    largest_drift = std::max(largest_drift, std::abs(state.energy_workspace.last.total - start));
    largest_contact = std::max(largest_contact, state.energy_workspace.last.contact);
  }
  EXPECT_GT(largest_contact, 0.05 * kinetic);  // the contact did store energy
  EXPECT_LT(largest_drift, 0.005 * kinetic);
  std::printf("elastic collision: balance within %.3g of the kinetic energy\n",
              largest_drift / kinetic);
  const ModelObject& thrown = model.objects[1];
  double momentum = 0.0;
  for (Index i = thrown.first_node; i < thrown.first_node + thrown.node_count; ++i) {
    momentum += model.node_mass[i] * state.velocity[i].z();
  }
  EXPECT_GT(momentum, 0.0);  // and it bounced
}

// A stiff bar dropped across a pinned wire at its middle, at the automatic stiffness and step,
// rebounds with the restitution of the contact's spring and damper to 2 %, whatever the instant
// within a step it touches (drops from eight heights an eighth of a step's travel apart): it
// stays in the penalty's soft layer, where a contact lasts some 20 steps.
TEST(ObjectContact, ReboundHasTheRestitutionOfTheDampingRatio) {
  for (const double zeta : {0.1, 0.3, 0.5}) {
    // Across the fixed wire between two of its nodes, so that one pair touches.
    const Model model =
        contact_scene(wire_at_wire(0.0, Vec3(0, 0.05, 0.011), Vec3(0, 0, -1), 1, 0.2),
                      fmt::format("{{objects: true, damping_ratio: {}}}", zeta));
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    const ModelObject& bar = model.objects[1];
    const double expected = test::restitution_of(zeta);
    double lowest = 1.0;
    double highest = 0.0;
    for (int drop = 0; drop < 8; ++drop) {
      State state = initial_state(model, dt);
      for (Index i = bar.first_node; i < bar.first_node + bar.node_count; ++i) {
        state.x[i].z() += dt * drop / 8.0;
      }
      while (state.time < 0.05) {
        step(model, dt, {}, state);
      }
      const double rebound =
          0.5 * (state.velocity[bar.first_node].z() + state.velocity[bar.first_node + 1].z());
      lowest = std::min(lowest, rebound);
      highest = std::max(highest, rebound);
    }
    std::printf("damping ratio %.1f: restitution %.4f to %.4f, closed form %.4f\n", zeta, lowest,
                highest, expected);
    EXPECT_NEAR(lowest, expected, 0.02 * expected) << zeta;
    EXPECT_NEAR(highest, expected, 0.02 * expected) << zeta;
  }
}

// A taut net of 1 mm cords, 1 m square in 10 × 10 cells at z = 1, its border pinned, drawn as wires
// (so only its cords touch), and a free rod of 6 cm above it at `speed` down; both of density 7850
// and Young's modulus `net_modulus` and `rod_modulus`. (Softer than steel, the test takes longer
// steps: the contact's physics does not depend on them.)
std::string rod_over_net(const Vec3& rod_centre, double speed, double net_modulus,
                         double rod_modulus) {
  return fmt::format(R"(  - name: net
    mesh:
      grid: {{width: 1.0, height: 1.0, columns: 10, rows: 10, diagonals: none}}
      translation: [-0.5, -0.5, 1.0]
    material: {{density: 7850, youngs_modulus: {4}, radius: 0.001}}
    pinned:
      box:
        - {{min: [-0.51, -0.51, 0.99], max: [-0.49, 0.51, 1.01]}}
        - {{min: [0.49, -0.51, 0.99], max: [0.51, 0.51, 1.01]}}
        - {{min: [-0.51, -0.51, 0.99], max: [0.51, -0.49, 1.01]}}
        - {{min: [-0.51, 0.49, 0.99], max: [0.51, 0.51, 1.01]}}
    style: wire
  - name: rod
    mesh: {{polyline: {{points: [[{0}, {1}, {2}], [{3}, {1}, {2}]]}}}}
    material: {{density: 7850, youngs_modulus: {5}, radius: 0.005}}
    contact: {{radius: 0.01}}
    initial_velocity: [0, 0, {6}]
)",
                     rod_centre.x() - 0.03, rod_centre.y(), rod_centre.z(), rod_centre.x() + 0.03,
                     net_modulus, rod_modulus, -speed);
}

// A rod dropped at 0.3 m/s on the taut net (E = 20 GPa, pretensioned to a strain of 10⁻² by
// stretching it, pins and all), across one cord at its middle and between the two cords it
// parallels, so that one contact point touches, rebounds with the restitution of a mass M on the
// contact's spring and damper. The contact (k = 50 N/m, given) is far softer than the net under a
// point load, so the net hardly gives (measured: its dip is under 2 % of the rod's, the tolerance).
// The damper is c = 2ζ√(k m) for the mass the contact point moves, m = 1/Σ w_j²/m_j over both
// sides' nodes (the light cord's nodes weigh in), so the rod's own ratio is ζ√(m/M). A ball would
// touch at several points at once, each damped for its own share of mass, which is why a rod.
TEST(ObjectContact, RodDroppedOnATautNetReboundsWithTheRestitutionOfItsDampingRatio) {
  for (const double zeta : {0.1, 0.3}) {
    const Model model =
        contact_scene(rod_over_net(Vec3(0, 0.05, 1.013), 0.3, 2.0e10, 2.0e9),
                      fmt::format("{{objects: true, stiffness: 50, damping_ratio: {}}}", zeta),
                      kNoGravityNoGround);
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    State state = initial_state(model, dt);
    const ModelObject& net = model.objects[0];
    const ModelObject& rod = model.objects[1];
    for (Index i = net.first_node; i < net.first_node + net.node_count; ++i) {
      state.x[i].head<2>() *= 1.01;
    }
    double moved_mass = 0.0;  // m, the mass the contact point moves
    std::size_t most_touching = 0;
    double rod_dip = 0.0;
    double net_dip = 0.0;
    while (state.time < 0.25) {
      step(model, dt, {}, state);
      const std::vector<ContactPoint>& touching = state.object_contact.previous;
      most_touching = std::max(most_touching, touching.size());
      if (touching.size() == 1) {
        double inverse = 0.0;
        for (int j = 0; j < 4; ++j) {
          inverse += touching[0].weights[j] * touching[0].weights[j] *
                     model.node_inv_mass[touching[0].nodes[j]];
        }
        moved_mass = 1.0 / inverse;
      }
      rod_dip = std::max(rod_dip, 1.013 - state.x[rod.first_node].z());
      for (Index i = net.first_node; i < net.first_node + net.node_count; ++i) {
        net_dip = std::max(net_dip, 1.0 - state.x[i].z());
      }
    }
    const double rod_mass = model.node_mass[rod.first_node] + model.node_mass[rod.first_node + 1];
    const double rebound =
        0.5 * (state.velocity[rod.first_node].z() + state.velocity[rod.first_node + 1].z()) / 0.3;
    const double expected = test::restitution_of(zeta * std::sqrt(moved_mass / rod_mass));
    std::printf(
        "taut net, damping ratio %.1f: restitution %.4f, closed form %.4f (ratio for the "
        "rod %.3f); the net dips %.3g m, the rod %.3g m\n",
        zeta, rebound, expected, zeta * std::sqrt(moved_mass / rod_mass), net_dip, rod_dip);
    EXPECT_EQ(most_touching, 1U);
    EXPECT_LT(net_dip, 0.02 * rod_dip);
    EXPECT_NEAR(rebound, expected, 0.02 * expected) << zeta;
  }
}

// A net drawn as wires has holes between its cords: a short rod dropped in the middle of a cell
// falls through. Asked to, its faces are shells that catch the rod and throw it back.
TEST(ObjectContact, NetDrawnAsWiresTouchesWithItsCordsOnlyUnlessItsFacesAreAsked) {
  for (const bool faces : {false, true}) {
    std::string objects = rod_over_net(Vec3(0.05, 0.05, 1.013), 1.0, 2.0e9, 2.0e9);
    objects.replace(objects.find("    style: wire\n"), 15,
                    fmt::format("    style: wire\n    contact: {{faces: {}}}\n", faces));
    const Model model = contact_scene(objects, "{objects: true}", kNoGravityNoGround);
    const double dt = kAutoTimestepSafety * critical_timestep(model);
    State state = initial_state(model, dt);
    while (state.time < 0.1) {
      step(model, dt, {}, state);
    }
    const double height = state.x[model.objects[1].first_node].z();
    if (faces) {
      EXPECT_GT(height, 1.0);
    } else {
      EXPECT_LT(height, 0.95);
    }
  }
}

// A stiff 0.2 m square of cross-braced bars (radius 5 mm) lying on a pinned 4 m cloth (radius
// 3 mm), just touching it (a square pressed in would be thrown off and land sliding), tilted by
// `degrees` about y, both placed in the cloth's plane and turned together; the
// slope descends towards +x along d = (cos θ, 0, −sin θ). Returns the square's centroid's
// distance down the slope over time.
std::vector<std::pair<double, double>> slide_on_cloth(double degrees, double duration) {
  const double theta = degrees * std::numbers::pi / 180.0;
  // Mesh placement turns about y, then translates: the square's offset in the cloth's plane,
  // turned the same way.
  const Vec3 offset(0.8 * std::cos(theta) + 0.008 * std::sin(theta), 2.6,
                    -0.8 * std::sin(theta) + 0.008 * std::cos(theta));
  const Model model =
      contact_scene(fmt::format(R"(  - name: slope
    mesh:
      grid: {{width: 4, height: 4, columns: 1, rows: 1, diagonals: one}}
      rotation: [0, {0}, 0]
    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.003}}
    pinned: {{all: true}}
  - name: block
    mesh:
      grid: {{width: 0.2, height: 0.2, columns: 2, rows: 2, diagonals: both}}
      rotation: [0, {0}, 0]
      translation: [{1}, {2}, {3}]
    material: {{density: 1000, youngs_modulus: 1.0e8, radius: 0.005}}
)",
                                degrees, offset.x(), offset.y(), offset.z()),
                    "{objects: true, friction: {static: 0.5, kinetic: 0.3}}",
                    "gravity: [0, 0, -9.81]\nground: {contact: false, visible: false}\n");
  const Vec3 downhill(std::cos(theta), 0, -std::sin(theta));
  const double dt = kAutoTimestepSafety * critical_timestep(model);
  State state = initial_state(model, dt);
  const ModelObject& block = model.objects[1];
  std::vector<std::pair<double, double>> track;
  while (state.time < duration) {
    step(model, dt, {}, state);
    Vec3 centroid = Vec3::Zero();
    for (Index i = block.first_node; i < block.first_node + block.node_count; ++i) {
      centroid += state.x[i];
    }
    track.emplace_back(state.time, centroid.dot(downhill) / block.node_count);
  }
  return track;
}

// Below the friction angle (tan 20° = 0.36 < μs = 0.5) the block stays where it landed, but for
// the stick springs' give (g sin θ / ω_c², micrometres).
TEST(ObjectContact, BlockOnAPinnedClothBelowTheFrictionAngleSticks) {
  const auto track = slide_on_cloth(20, 1.0);
  EXPECT_LT(std::abs(track.back().second - track.front().second), 1e-4);
}

// Above it (tan 35° = 0.70 > μs) it slides with a = g (sin θ − μk cos θ), within 2 %: a least-
// squares fit s = s0 + v0 t + ½ a t² over t ∈ [0.2, 0.8] s, after the landing.
TEST(ObjectContact, BlockOnAPinnedClothAboveTheFrictionAngleSlidesWithKineticFriction) {
  const double degrees = 35;
  const double theta = degrees * std::numbers::pi / 180.0;
  const auto track = slide_on_cloth(degrees, 0.8);
  const double acceleration = test::fitted_acceleration(track, 0.2);
  const double expected = kG * (std::sin(theta) - 0.3 * std::cos(theta));
  EXPECT_NEAR(acceleration / expected, 1.0, 0.02);
  std::printf("block on a pinned cloth at 35°: a = %.4f m/s², closed form %.4f\n", acceleration,
              expected);
}

}  // namespace
}  // namespace dinam
