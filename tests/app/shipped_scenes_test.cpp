// The shipped scenes: each loads, and its motion does what the scene promises.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "app/frame_source.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

SceneDescription shipped(const std::string& name) {
  return read_scene(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes" / (name + ".yaml"));
}

// Every frame of a scene at its own time step.
SimulatedFrames simulate_scene(const SceneDescription& scene, const Model& model,
                               bool track_energy = false,
                               const std::function<void(int, const State&)>& on_frame = {}) {
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  return simulate_frames(model, timestep, scene.frame_count(), track_energy, on_frame);
}

// The lowest height any node reaches in frames first … last.
double lowest_height(const SimulatedFrames& frames, std::size_t first = 0) {
  double lowest = std::numeric_limits<double>::max();
  for (std::size_t f = first; f < frames.positions.size(); ++f) {
    for (const Vec3f& x : frames.positions[f]) {
      lowest = std::min(lowest, static_cast<double>(x.z()));
    }
  }
  return lowest;
}

TEST(ShippedScenes, FlagIsA120FrameSixSecondScene) {
  const SceneDescription scene = shipped("flag");
  EXPECT_EQ(scene.frame_count(), 120);
  EXPECT_DOUBLE_EQ(scene.frame_count() / scene.fps, 6.0);
  EXPECT_EQ(scene.image_width, 1280);
  EXPECT_EQ(scene.image_height, 720);
}

// The paper's falling ball: it lands, turns about its centre of mass (stick friction converts
// travel into spin), vibrates and comes to rest, and never sinks into the ground beyond the
// penalty's give.
TEST(ShippedScenes, BallLandsTurnsAndComesToRest) {
  const SceneDescription scene = shipped("ball");
  const Model model = build_model(scene);
  double peak_kinetic = 0.0;
  double final_kinetic = 0.0;
  const SimulatedFrames frames = simulate_scene(scene, model, true, [&](int, const State& state) {
    peak_kinetic = std::max(peak_kinetic, state.energy_workspace.last.kinetic);
    final_kinetic = state.energy_workspace.last.kinetic;
  });

  const double lowest = lowest_height(frames);
  // It lands: some node reaches the plane. At most it sinks by the impact speed over the contact
  // frequency (|v| ≤ 3.6 m/s at first touch; ω_c from the auto stiffness).
  const double contact_omega = std::sqrt(model.ground.node_stiffness[0] / model.node_mass[0]);
  EXPECT_LT(lowest, 1e-3);
  EXPECT_GT(lowest, -4.0 / contact_omega);

  // It turns: the direction from the centroid to the node that started on top swings round.
  auto centroid = [](const std::vector<Vec3f>& positions) {
    Vec3f c = Vec3f::Zero();
    for (const Vec3f& x : positions) {
      c += x;
    }
    return Vec3f(c / static_cast<float>(positions.size()));
  };
  Index top = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    top = model.node_initial_x[i].z() > model.node_initial_x[top].z() ? i : top;
  }
  const Vec3f before =
      (frames.positions.front()[top] - centroid(frames.positions.front())).normalized();
  const Vec3f after =
      (frames.positions.back()[top] - centroid(frames.positions.back())).normalized();
  const double turned = std::acos(std::clamp(static_cast<double>(before.dot(after)), -1.0, 1.0));
  EXPECT_GT(turned, 20.0 * std::numbers::pi / 180.0);

  // It comes to rest before the end.
  EXPECT_LT(final_kinetic, 0.01 * peak_kinetic);
}

// The cloth's centroid in frames 61 … 120 of a flag scene.
std::vector<Vec3f> cloth_centroids(const SceneDescription& scene, const Model& model) {
  const SimulatedFrames frames = simulate_scene(scene, model);
  const ModelObject& cloth = model.objects[1];
  std::vector<Vec3f> centroids;
  for (std::size_t f = 60; f < frames.positions.size(); ++f) {
    Vec3f c = Vec3f::Zero();
    for (Index i = 0; i < cloth.node_count; ++i) {
      c += frames.positions[f][cloth.first_node + i];
    }
    centroids.push_back(c / static_cast<float>(cloth.node_count));
  }
  // It stays attached: the hoist nodes are where they started.
  for (Index i = 0; i < cloth.node_count; ++i) {
    const Index node = cloth.first_node + i;
    if (model.pinned(node)) {
      EXPECT_EQ(frames.positions.back()[node], model.node_initial_x[node].cast<float>());
    }
  }
  return centroids;
}

// The flag in gusty wind streams out downwind and stays up through the second half; the same
// flag in calm air swings back across the pole and droops (the control shows the check bites).
TEST(ShippedScenes, WindyFlagStreamsDownwind) {
  SceneDescription scene = shipped("windy_flag");
  for (const Vec3f& c : cloth_centroids(scene, build_model(scene))) {
    EXPECT_GT(c.x(), 0.5f);   // a flat 1.5 m flag has its centroid at 0.75 m
    EXPECT_GT(c.z(), 2.45f);  // and at 2.7 m height
  }
  scene.wind.velocity = Vec3(1e-3, 0, 0);
  scene.wind.gust_amplitude = 0.0;
  scene.wind.turbulence = 0.0;
  double lowest_x = 1e9;
  for (const Vec3f& c : cloth_centroids(scene, build_model(scene))) {
    lowest_x = std::min(lowest_x, static_cast<double>(c.x()));
  }
  EXPECT_LT(lowest_x, 0.5);
}

// The trampoline: the load that lands at 2.5 s drives the centre down, past where it ends up (a
// step load overshoots its final deflection), the rim holds, and nothing reaches the ground.
TEST(ShippedScenes, TrampolineBouncesUnderTheSuddenLoad) {
  const SceneDescription scene = shipped("trampoline");
  const Model model = build_model(scene);
  const SimulatedFrames frames = simulate_scene(scene, model);
  Index center = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.node_initial_x[i].head<2>().norm() < model.node_initial_x[center].head<2>().norm()) {
      center = i;
    }
  }
  const double rest_height = model.node_initial_x[center].z();
  auto deflection = [&](std::size_t frame) {
    return rest_height - static_cast<double>(frames.positions[frame][center].z());
  };
  const double before = deflection(49);  // t = 2.45 s, just before the load
  double peak = 0.0;
  for (std::size_t f = 50; f < frames.positions.size(); ++f) {
    peak = std::max(peak, deflection(f));
  }
  const double lowest = lowest_height(frames, 50);
  const double end = deflection(frames.positions.size() - 1);
  EXPECT_GT(end, before + 0.2);  // 360 N pushes the middle well down
  EXPECT_GT(peak, 1.1 * end);    // and it bounced past where it settles
  EXPECT_GT(lowest, 0.0);        // the ground, 1 m below the frame, is never reached
  for (Index i = 0; i < model.node_count(); ++i) {
    if (model.pinned(i)) {
      EXPECT_EQ(frames.positions.back()[i], model.node_initial_x[i].cast<float>());
    }
  }
}

// The rope: it swings down and its lower part comes to lie still on the ground (the hanging part
// may still sway), never sinking into it beyond the contact's give; the held end stays put.
TEST(ShippedScenes, RopeLandsAndRestsOnTheGround) {
  const SceneDescription scene = shipped("rope");
  const Model model = build_model(scene);
  const SimulatedFrames frames = simulate_scene(scene, model);
  EXPECT_GT(lowest_height(frames),
            -0.01);  // the swing lands at a few m/s: millimetres of penalty give
  const std::vector<Vec3f>& last = frames.positions.back();
  const std::vector<Vec3f>& earlier = frames.positions[frames.positions.size() - 11];
  int resting = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    resting += last[i].z() < 0.02f ? 1 : 0;
  }
  EXPECT_GT(resting, model.node_count() * 3 / 10);  // a good part of the rope lies on the ground
  // Its free end, farthest from the swaying part, lies still there (over the last half second),
  // held by friction; nodes near the touchdown point are still dragged a little by the sway.
  const Index free_end = model.node_count() - 1;
  EXPECT_LT(last[free_end].z(), 0.02f);
  EXPECT_LT((last[free_end] - earlier[free_end]).norm(), 0.005f);
  EXPECT_EQ(last[0], model.node_initial_x[0].cast<float>());
}

}  // namespace
}  // namespace dinam
