#include "render/camera.hpp"

#include <gtest/gtest.h>

namespace dinam {
namespace {

TEST(Camera, LookAtPointIsTheImageCentre) {
  RenderCamera camera;
  camera.position = Vec3f(3, -4, 2);
  camera.look_at = Vec3f(0, 0, 1);
  const Eigen::Vector2f pixel = pixel_from_world(camera, 640, 360, camera.look_at);
  EXPECT_NEAR(pixel.x(), 320.0f, 1e-3f);
  EXPECT_NEAR(pixel.y(), 180.0f, 1e-3f);
}

TEST(Camera, VerticalFieldOfViewSpansTheImageHeight) {
  // Looking along +y from the origin with a 90° field of view, a point 1 m ahead and 1 m up
  // (45° above the axis) lies on the top edge; 1 m to the right at 16:9 lies at 9/16 of the
  // half width beyond the centre (right = forward × up = +x).
  RenderCamera camera;
  camera.position = Vec3f(0, 0, 0);
  camera.look_at = Vec3f(0, 1, 0);
  camera.up = Vec3f(0, 0, 1);
  camera.fov_degrees = 90.0f;
  const Eigen::Vector2f top = pixel_from_world(camera, 1600, 900, Vec3f(0, 1, 1));
  EXPECT_NEAR(top.y(), 0.0f, 1e-3f);
  const Eigen::Vector2f right = pixel_from_world(camera, 1600, 900, Vec3f(1, 1, 0));
  EXPECT_NEAR(right.x(), 800.0f + 800.0f * 9.0f / 16.0f, 1e-2f);
}

}  // namespace
}  // namespace dinam
