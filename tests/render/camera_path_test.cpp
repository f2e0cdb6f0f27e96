// Cameras that move by themselves: a path through keys and an orbit, checked against what a key
// and a circle require, without drawing.
#include "render/camera_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dinam {
namespace {

std::vector<CameraKey> three_keys() {
  return {{0.0, Vec3f(4, -6, 2), Vec3f(0, 0, 1), 40.0f},
          {1.0, Vec3f(0, -5, 3), Vec3f(0, 0, 1.5f), 30.0f},
          {3.0, Vec3f(-4, -2, 2), Vec3f(1, 0, 1), 50.0f}};
}

TEST(CameraPath, PassesThroughEveryKeyAndHoldsOutsideThem) {
  const std::vector<CameraKey> keys = three_keys();
  for (const CameraKey& key : keys) {
    const RenderCamera c = camera_on_path(keys, key.time, Vec3f::UnitZ());
    EXPECT_TRUE(c.position.isApprox(key.position, 1e-6f));
    EXPECT_TRUE(c.look_at.isApprox(key.look_at, 1e-6f));
    EXPECT_FLOAT_EQ(c.fov_degrees, key.fov_degrees);
  }
  EXPECT_EQ(camera_on_path(keys, -1.0, Vec3f::UnitZ()).position, keys.front().position);
  EXPECT_EQ(camera_on_path(keys, 9.0, Vec3f::UnitZ()).position, keys.back().position);
}

// Velocity by central differences: continuous through the middle key (no kink, though the keys
// are unevenly spaced in time), zero at the first and last key (the camera eases in and out),
// and at the middle key the slope between its neighbours (Catmull–Rom).
TEST(CameraPath, MovesWithoutKinksAndEasesInAndOut) {
  const std::vector<CameraKey> keys = three_keys();
  const double h = 1e-4;
  const auto at = [&](double t) { return camera_on_path(keys, t, Vec3f::UnitZ()).position; };
  const auto velocity = [&](double t0, double t1) {
    return Vec3f((at(t1) - at(t0)) / static_cast<float>(t1 - t0));
  };
  const Vec3f before = velocity(1.0 - 2 * h, 1.0 - h);
  const Vec3f after = velocity(1.0 + h, 1.0 + 2 * h);
  const Vec3f catmull_rom = (keys[2].position - keys[0].position) / 3.0f;
  // Differences over 0.1 ms are off the velocity at the key by about the acceleration × 0.15 ms
  // (under 3 mm/s here), and single-precision positions add under 5 mm/s.
  EXPECT_LT((before - catmull_rom).norm(), 0.01f);
  EXPECT_LT((after - catmull_rom).norm(), 0.01f);
  EXPECT_LT(velocity(0.0, h).norm(), 0.01f);
  EXPECT_LT(velocity(3.0 - h, 3.0).norm(), 0.01f);
}

TEST(CameraPath, OrbitCirclesItsCentreAtItsHeightLookingAtIt) {
  const Vec3f center(1, 2, 0.5f);
  for (const float angle : {0.0f, 1.0f, 2.5f, 4.0f}) {
    const RenderCamera c = orbit_camera(center, 5.0f, 2.0f, angle, Vec3f::UnitZ(), 35.0f);
    EXPECT_EQ(c.look_at, center);
    EXPECT_NEAR(c.position.z() - center.z(), 2.0f, 1e-5f);
    EXPECT_NEAR((c.position - center).head<2>().norm(), 5.0f, 1e-5f);
    // `angle` is measured around up from +x.
    EXPECT_NEAR(std::atan2(c.position.y() - center.y(), c.position.x() - center.x()),
                std::remainder(angle, 2.0f * std::numbers::pi_v<float>), 1e-5f);
  }
}

}  // namespace
}  // namespace dinam
