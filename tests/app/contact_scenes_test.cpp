// The shipped scenes of objects that touch, against what contact promises: nothing passes
// through anything, at any frame, and the objects rest on each other rather than falling apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

#include "app/shipped_scenes.hpp"
#include "core/closest_points.hpp"
#include "dynamics/contact/contact_grid.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "run/frame_source.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

using test::shipped;
using test::simulate_scene;

// True when segment p–q passes through triangle a, b, c (Möller and Trumbore, 1997).
bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  const Vec3 direction = q - p;
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 h = direction.cross(ac);
  const double det = ab.dot(h);
  if (std::abs(det) < 1e-300) {
    return false;  // parallel to the plane
  }
  const Vec3 s = p - a;
  const double u = s.dot(h) / det;
  const Vec3 k = s.cross(ab);
  const double v = direction.dot(k) / det;
  const double t = ac.dot(k) / det;
  return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t >= 0.0 && t <= 1.0;
}

// The bars (of any object) that pass through a triangle of the model's contact that they share
// no node with and are not neighbours of (docs/scene-format.md: a node of one joined by a bar to
// a node of the other never touch), at the given positions: two objects, or one object and
// itself, interpenetrating where contact should have held them apart.
int crossings(const Model& model, const std::vector<Vec3f>& positions) {
  const ObjectContact& contact = model.contact;
  std::vector<Vec3> x(positions.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = positions[i].cast<double>();
  }
  const auto triangles = static_cast<Index>(contact.triangle_face.size());
  std::vector<Box> boxes(triangles);
  for (Index t = 0; t < triangles; ++t) {
    const Index* c = &contact.triangles[3 * t];
    boxes[t] = {x[c[0]].cwiseMin(x[c[1]]).cwiseMin(x[c[2]]),
                x[c[0]].cwiseMax(x[c[1]]).cwiseMax(x[c[2]])};
  }
  ContactGrid grid;
  grid.build(boxes, {}, 0.0);
  int count = 0;
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    grid.visit_overlapping({x[n0].cwiseMin(x[n1]), x[n0].cwiseMax(x[n1])}, [&](Index t) {
      const Index* c = &contact.triangles[3 * t];
      bool excluded = false;
      for (int k = 0; k < 3; ++k) {
        excluded = excluded || n0 == c[k] || n1 == c[k] || contact.joined(n0, c[k]) ||
                   contact.joined(n1, c[k]);
      }
      if (!excluded && segment_crosses_triangle(x[n0], x[n1], x[c[0]], x[c[1]], x[c[2]])) {
        ++count;
      }
    });
  }
  return count;
}

// The cloth dropped over the fixed wire chair: at no frame does a bar (the chair's wires or the
// cloth's own threads beyond their neighbours) pass through the cloth, and at the end it rests on
// the chair: the cloth over the seat (|x|, |y| < 0.2 m) is held at the seat's height, 0.45 m, by
// its wires. The control: without contact the cloth falls through the chair to the floor, and
// crosses it.
TEST(ShippedScenes, ClothDrapedOverTheChairNeverPassesThroughAndRestsOnIt) {
  SceneDescription scene = shipped("draped_chair");
  auto lowest_over_seat = [](const Model& model, const std::vector<Vec3f>& positions) {
    const ModelObject& cloth = model.objects[1];
    double lowest = 1e9;
    for (Index i = cloth.first_node; i < cloth.first_node + cloth.node_count; ++i) {
      const Vec3f& p = positions[i];
      if (std::abs(p.x()) < 0.2f && std::abs(p.y()) < 0.2f) {
        lowest = std::min(lowest, static_cast<double>(p.z()));
      }
    }
    return lowest;
  };
  const Model model = build_model(scene);
  const SimulatedFrames frames = simulate_scene(scene, model);
  int crossed = 0;
  for (const std::vector<Vec3f>& positions : frames.positions) {
    crossed += crossings(model, positions);
  }
  EXPECT_EQ(crossed, 0);
  EXPECT_GT(lowest_over_seat(model, frames.positions.back()), 0.40);

  scene.contact = ContactDesc{};  // no contact
  const Model loose = build_model(scene);
  const SimulatedFrames fallen = simulate_scene(scene, loose);
  EXPECT_LT(lowest_over_seat(loose, fallen.positions.back()), 0.1);
  int crossed_loose = 0;
  for (const std::vector<Vec3f>& positions : fallen.positions) {
    crossed_loose += crossings(model, positions);  // the contact model's triangles, same mesh
  }
  EXPECT_GT(crossed_loose, 0);
}

// Wires passing through each other between two samples of the motion, close enough in time that
// no wire moves by more than a fraction of a contact radius between them: pairs of bars that
// contact covers (of two objects that touch, or of one that touches itself, not neighbours in
// the mesh) whose closest points lie inside both bars at both samples, within `near`, and whose
// separation turns round (its direction at one sample against the other's). Wires that slide
// along each other, roll round each other's ends or turn through parallel keep their separation's
// direction; wires that pass through each other reverse it.
int wire_crossings(const Model& model, const std::vector<Vec3>& before,
                   const std::vector<Vec3>& after, double near) {
  const ObjectContact& contact = model.contact;
  const Index bars = model.bar_count();
  std::vector<Box> boxes(bars);
  for (Index b = 0; b < bars; ++b) {
    const Vec3& p = after[model.bar_nodes[2 * b]];
    const Vec3& q = after[model.bar_nodes[2 * b + 1]];
    boxes[b] = {p.cwiseMin(q).array() - near, p.cwiseMax(q).array() + near};
  }
  ContactGrid grid;
  grid.build(boxes, {}, 0.0);
  // The separation of the closest points when they lie inside both bars, else nothing.
  auto inner_separation = [&](const std::vector<Vec3>& x, Index a0, Index a1, Index b0,
                              Index b1) -> std::optional<Vec3> {
    const SegmentPair c = closest_points_of_segments(x[a0], x[a1], x[b0], x[b1]);
    if (c.s <= 0.0 || c.s >= 1.0 || c.t <= 0.0 || c.t >= 1.0) {
      return std::nullopt;
    }
    const Vec3 separation = x[a0] + c.s * (x[a1] - x[a0]) - x[b0] - c.t * (x[b1] - x[b0]);
    return separation.squaredNorm() < near * near ? std::optional(separation) : std::nullopt;
  };
  int count = 0;
  for (Index a = 0; a < bars; ++a) {
    const Index a0 = model.bar_nodes[2 * a];
    const Index a1 = model.bar_nodes[2 * a + 1];
    const Index object_a = model.node_object[a0];
    grid.visit_overlapping(boxes[a], [&](Index b) {
      const Index b0 = model.bar_nodes[2 * b];
      const Index b1 = model.bar_nodes[2 * b + 1];
      const Index object_b = model.node_object[b0];
      const bool covered = object_a == object_b ? contact.object_self[object_a] != 0
                                                : contact.object_between[object_a] != 0 &&
                                                      contact.object_between[object_b] != 0;
      if (b <= a || !covered || a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1 ||
          contact.joined(a0, b0) || contact.joined(a0, b1) || contact.joined(a1, b0) ||
          contact.joined(a1, b1)) {
        return;
      }
      const std::optional<Vec3> then = inner_separation(before, a0, a1, b0, b1);
      const std::optional<Vec3> now = inner_separation(after, a0, a1, b0, b1);
      if (then && now && then->dot(*now) < 0.0) {
        ++count;
      }
    });
  }
  return count;
}

// Counts wire crossings (above) between consecutive samples of a motion, within 3 cm, by the
// contact rule of `judge`.
struct CrossingCounter {
  explicit CrossingCounter(const Model& model) : judge(model) {}

  const Model& judge;
  std::vector<Vec3> before;
  int crossed = 0;

  void sample(const std::vector<Vec3>& x) {
    if (!before.empty()) {
      crossed += wire_crossings(judge, before, x, 0.03);
    }
    before = x;
  }
};

// Steps a shipped scene from rest to its last frame, calling `sample` with the positions every
// `interval` seconds (to the nearest step) and `on_frame` with the state at every frame.
void run_sampled(const SceneDescription& scene, const Model& model, double interval,
                 const std::function<void(const std::vector<Vec3>&)>& sample,
                 const std::function<void(const State&)>& on_frame) {
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const int stride = std::max(1, static_cast<int>(std::lround(interval / timestep.dt)));
  State state = initial_state(model, timestep.dt);
  for (int frame = 1; frame <= scene.frame_count(); ++frame) {
    for (int s = 0; s < timestep.steps_per_frame; ++s) {
      step(model, timestep.dt, {}, state);
      if (state.step % stride == 0) {
        sample(state.x);
      }
    }
    on_frame(state);
  }
}

// A square of cloth hanging by nothing, its lower edge just above the floor, let go: it
// crumples onto the floor and folds over itself several times. With self-contact no bar passes
// through a triangle of the cloth beyond its mesh neighbours at any sample of the run (every 2 ms,
// when no node moves more than 1 cm); the control, without self-contact, folds through itself.
// The step is given: contact holds while v Δt < 0.8 × the radius (docs/scene-format.md), and a
// fold's free edge whips at up to about 17 m/s (one node 35 mm in a 2 ms sample), past the 12 m/s
// that the automatic step of 0.32 ms allows with these 5 mm radii. At that step whether some
// bar went through depended on the rounding: 0, 6, 2 388 and 3 274 bars through at global
// damping 0.29, 0.30, 0.31 and 0.33; at 0.1 ms (40 m/s) none in any of them.
TEST(SelfContact, ClothCrumplingOnTheFloorFoldsOnItselfWithoutPassingThrough) {
  auto cloth = [](bool self) {
    return test::scene_from_yaml(std::string(R"(version: 1
duration: 1.5
fps: 20
timestep: 0.0001
gravity: [0, 0, -9.81]
damping: {global: 0.3}
ground: {height: 0, friction: {static: 0.5, kinetic: 0.4}}
)") + (self ? "contact: {self: true, damping_ratio: 0.3}\n" : "") +
                                 R"(objects:
  - name: cloth
    mesh:
      grid: {width: 0.8, height: 0.8, columns: 24, rows: 24, diagonals: one}
      rotation: [80, 0, 0]
      translation: [-0.4, 0, 0.02]
    material: {density: 1200, youngs_modulus: 5.0e6, radius: 0.001}
    contact: {radius: 0.005}
)");
  };
  const SceneDescription scene = cloth(true);
  const Model judge = build_model(scene);
  auto crossed_in = [&judge](const SceneDescription& variant) {
    const Model model = build_model(variant);
    int crossed = 0;
    double top = 0.0;
    std::vector<Vec3f> positions;
    run_sampled(
        variant, model, 2e-3,
        [&](const std::vector<Vec3>& x) {
          positions.resize(x.size());
          for (std::size_t i = 0; i < x.size(); ++i) {
            positions[i] = x[i].cast<float>();
          }
          crossed += crossings(judge, positions);
        },
        [&](const State& state) {
          top = 0.0;
          for (const Vec3& p : state.x) {
            top = std::max(top, p.z());
          }
        });
    std::printf("%d crossings; the cloth ends %.3f m high\n", crossed, top);
    return std::pair{crossed, top};
  };
  const auto [crossed, top] = crossed_in(scene);
  EXPECT_EQ(crossed, 0);
  EXPECT_LT(top, 0.2);  // it did fall and fold: 0.8 m of cloth in a pile
  EXPECT_GT(crossed_in(cloth(false)).first, 0);
}

// The paper's soft ball thrown into the trampoline's net: no wire of the ball passes between the
// net's cords (wire crossings sampled every 0.2 ms, when no wire moves more than a millimetre), the
// net catches it well above the floor and throws it back up, and at the end it lies in the net.
// The control: without contact the ball falls through the net onto the floor, its wires
// crossing the cords.
TEST(ShippedScenes, BallThrownIntoTheNetIsCaughtAndThrownBackWithNoWirePassingACord) {
  struct Track {
    int crossed = 0;
    double lowest = 1e9;         // m, the ball's lowest node at any sample
    std::vector<double> centre;  // m, the ball's centroid's height at every frame
  };
  // Crossings are judged by the contact model's rule, also for the control's motion.
  SceneDescription scene = shipped("ball_in_net");
  const Model judge = build_model(scene);
  auto run = [&judge](const SceneDescription& variant) {
    const Model model = build_model(variant);
    const ModelObject& ball = test::object_named(model, "ball");
    Track track;
    CrossingCounter counter(judge);
    run_sampled(
        variant, model, 2e-4,
        [&](const std::vector<Vec3>& x) {
          counter.sample(x);
          for (Index i = ball.first_node; i < ball.first_node + ball.node_count; ++i) {
            track.lowest = std::min(track.lowest, x[i].z());
          }
        },
        [&](const State& state) {
          double height = 0.0;
          for (Index i = ball.first_node; i < ball.first_node + ball.node_count; ++i) {
            height += state.x[i].z();
          }
          track.centre.push_back(height / ball.node_count);
        });
    track.crossed = counter.crossed;
    return track;
  };
  const Track caught = run(scene);
  const auto bottom = std::min_element(caught.centre.begin(), caught.centre.end());
  const double rebound = *std::max_element(bottom, caught.centre.end()) - *bottom;
  std::printf(
      "ball in the net: %d crossings, lowest node %.3f m, centre down to %.3f m, "
      "rebound %.3f m, ends at %.3f m\n",
      caught.crossed, caught.lowest, *bottom, rebound, caught.centre.back());
  EXPECT_EQ(caught.crossed, 0);
  EXPECT_GT(caught.lowest, 0.3);
  EXPECT_GT(rebound, 0.2);

  scene.contact = ContactDesc{};  // no contact
  scene.duration = 1.0;
  const Track fallen = run(scene);
  std::printf("without contact: %d crossings, lowest node %.3f m\n", fallen.crossed, fallen.lowest);
  EXPECT_GT(fallen.crossed, 0);
  EXPECT_LT(fallen.lowest, 0.05);
}

// Mass scaling's limit is a share of what moves: the ball in the net's pinned steel frame (about
// 190 kg, 50 times the ball and the net) lends it nothing, so the few stiff nodes of the ball take
// at most 2 % of the free nodes' mass (it was 3.85 kg, twice the ball, while the frame counted).
TEST(ShippedScenes, APinnedFrameLendsMassScalingNothing) {
  const Model model = build_model(shipped("ball_in_net"));
  double free = 0.0;
  double pinned = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    (model.pinned(i) ? pinned : free) += model.node_mass[i];
  }
  const double physical_free = free - model.mass_scaling.added_mass;
  EXPECT_GT(pinned, 20.0 * physical_free);
  EXPECT_LE(model.mass_scaling.added_mass, kDefaultMaxAddedMass * physical_free * (1.0 + 1e-9));
  if (model.mass_scaling.nodes > 0) {  // (within 2 % of what moves, scaling no longer pays here)
    EXPECT_NEAR(model.mass_scaling.mass_before, physical_free, 1e-9 * physical_free);
  }
}

// A rope paid out in loose turns falls into a heap: no wire passes through another at any sample
// (every 0.2 ms), and the turns lie on top of each other: more than 10 % of the rope rests on
// turns below (its axis above two radii; the ground holds nodes at their radius, z = r, a turn on
// another lies at 3 r), the top at least as high as a turn lying on another (3 r), the rope's
// 3.5 m within 0.75 m. (Measured: 51 % on top, 43.5 mm high, 0.30 m across; without
// self-contact none on top, 7.3 mm high.) The control: without self-contact the turns pass
// through each other and lie flat on the floor.
TEST(ShippedScenes, RopeDroppedOnTheFloorCoilsIntoAHeapWithoutPassingThroughItself) {
  struct Heap {
    int crossed = 0;
    double height = 0.0;  // m, the rope's highest node at the last frame
    double spread = 0.0;  // m, the larger horizontal side of its box at the last frame
    double on_top = 0.0;  // the fraction of its nodes lying on a turn below (z > 2 r)
  };
  constexpr double kRadius = 0.006;  // m, the rope's
  SceneDescription scene = shipped("rope_heap");
  const Model judge = build_model(scene);
  auto run = [&judge](const SceneDescription& variant) {
    const Model model = build_model(variant);
    Heap heap;
    CrossingCounter counter(judge);
    run_sampled(
        variant, model, 2e-4, [&](const std::vector<Vec3>& x) { counter.sample(x); },
        [&](const State& state) {
          Vec3 low = Vec3::Constant(1e9);
          Vec3 high = Vec3::Constant(-1e9);
          for (const Vec3& p : state.x) {
            low = low.cwiseMin(p);
            high = high.cwiseMax(p);
          }
          heap.height = high.z();
          heap.on_top = 0.0;
          for (const Vec3& p : state.x) {
            heap.on_top += p.z() > 2.0 * kRadius ? 1.0 : 0.0;
          }
          heap.on_top /= static_cast<double>(state.x.size());
          heap.spread = std::max(high.x() - low.x(), high.y() - low.y());
        });
    heap.crossed = counter.crossed;
    return heap;
  };
  const Heap heap = run(scene);
  std::printf("rope heap: %d crossings, %.4f m high, %.3f m across, %.3f on top\n", heap.crossed,
              heap.height, heap.spread, heap.on_top);
  EXPECT_EQ(heap.crossed, 0);
  EXPECT_GT(heap.on_top, 0.10);
  EXPECT_GT(heap.height, 3.0 * kRadius);  // turns on turns (the ground holds nodes at z = r)
  EXPECT_LT(heap.spread, 0.25 * 3.0);

  scene.contact = ContactDesc{};
  const Heap flat = run(scene);
  std::printf("without self-contact: %d crossings, %.4f m high, %.3f m across, %.3f on top\n",
              flat.crossed, flat.height, flat.spread, flat.on_top);
  EXPECT_GT(flat.crossed, 0);
  EXPECT_LT(flat.on_top, 0.02);
}

// No shipped scene shows one object's wire through another's at any frame: two drawn bars of
// different objects whose axes come nearer than half the sum of their drawn radii, having
// started farther apart (a wire tied to a post is modelled touching it, and stays so). Scenes
// with fewer than two objects drawn with wires have nothing to check and are not simulated.
TEST(ShippedScenes, NoSceneShowsAWireThroughAnotherObjectsWire) {
  for (const std::filesystem::directory_entry& entry :
       std::filesystem::directory_iterator(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".yaml") {
      continue;
    }
    const SceneDescription scene = shipped(entry.path().stem().string());
    const Model model = build_model(scene);
    std::vector<Vec3f> at_rest(model.node_initial_x.size());
    for (std::size_t i = 0; i < at_rest.size(); ++i) {
      at_rest[i] = model.node_initial_x[i].cast<float>();
    }
    const DrawList start = make_draw_list(scene, model, motion_bounds({at_rest}));
    std::vector<Index> wired_objects;
    for (std::size_t s = 0; s < start.segment_radius.size(); ++s) {
      wired_objects.push_back(model.node_object[start.segment_points[2 * s]]);
    }
    std::sort(wired_objects.begin(), wired_objects.end());
    if (std::unique(wired_objects.begin(), wired_objects.end()) - wired_objects.begin() < 2) {
      continue;
    }
    const SimulatedFrames frames = simulate_scene(scene, model);
    // Pairs of segments of different objects, and whether each started apart.
    const std::vector<Index>& points = start.segment_points;
    const auto segments = static_cast<Index>(start.segment_radius.size());
    auto gap = [&](const std::vector<Vec3f>& x, Index a, Index b) {
      const Vec3 p0 = x[points[2 * a]].cast<double>();
      const Vec3 p1 = x[points[2 * a + 1]].cast<double>();
      const Vec3 q0 = x[points[2 * b]].cast<double>();
      const Vec3 q1 = x[points[2 * b + 1]].cast<double>();
      const SegmentPair c = closest_points_of_segments(p0, p1, q0, q1);
      const double axes = (p0 + c.s * (p1 - p0) - q0 - c.t * (q1 - q0)).norm();
      return axes - 0.5 * (std::abs(start.segment_radius[a]) + std::abs(start.segment_radius[b]));
    };
    std::vector<std::pair<Index, Index>> pairs;
    for (Index a = 0; a < segments; ++a) {
      for (Index b = a + 1; b < segments; ++b) {
        if (model.node_object[points[2 * a]] != model.node_object[points[2 * b]] &&
            gap(frames.positions.front(), a, b) > 0.0) {
          pairs.emplace_back(a, b);
        }
      }
    }
    int through = 0;
    for (const std::vector<Vec3f>& x : frames.positions) {
      for (const auto& [a, b] : pairs) {
        through += gap(x, a, b) < 0.0 ? 1 : 0;
      }
    }
    std::printf("%s: %zu pairs of wires of different objects, %d pair-frames through\n",
                scene.name.c_str(), pairs.size(), through);
    if (scene.name == "flag") {
      // The paper's flag has no contact, as in the paper: its ties and halyard, swinging about
      // their knots on the pole, cut into it by up to 16 mm in 30 of its 55 781 pair-frames.
      // Contact between the two keeps its settling from converging (relaxation, the cloth
      // sliding on the pole: 0.44 of a node's weight out of balance after 60 s). Bounded here,
      // at 0.1 %, until it has a way to settle with contact.
      EXPECT_LE(through, static_cast<int>(
                             1e-3 * static_cast<double>(pairs.size() * frames.positions.size())));
    } else {
      EXPECT_EQ(through, 0) << scene.name;
    }
  }
}

}  // namespace
}  // namespace dinam
