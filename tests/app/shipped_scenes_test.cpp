// The shipped scenes: each loads, and its motion does what the scene promises.
#include <gtest/gtest.h>

#include <cmath>
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
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  double peak_kinetic = 0.0;
  double final_kinetic = 0.0;
  const SimulatedFrames frames =
      simulate_frames(model, timestep, scene.frame_count(), true, [&](int, const State& state) {
        peak_kinetic = std::max(peak_kinetic, state.energy_workspace.last.kinetic);
        final_kinetic = state.energy_workspace.last.kinetic;
      });

  double lowest = 1e9;
  for (const auto& positions : frames.positions) {
    for (const Vec3f& x : positions) {
      lowest = std::min(lowest, static_cast<double>(x.z()));
    }
  }
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

}  // namespace
}  // namespace dinam
