// The cyclorama: its surface as made (on the plane at its radius, curving up into a wall, lit
// from inside), and its size for the run's cameras, checked by geometry: every camera inside it,
// and the upper edge of every picture meeting the wall below its top.
#include "visual/backdrop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/cyclorama_mesh.hpp"

namespace dinam {
namespace {

TEST(Cyclorama, RisesFromThePlaneAtItsRadiusIntoAWallFacingTheAxis) {
  const Vec3f center(1.0f, -2.0f, 0.5f);
  const PrimitiveMesh mesh = make_cyclorama(center, Vec3f::UnitZ(), 4.0f, 1.0f, 6.0f, 64, 8);
  ASSERT_EQ(mesh.vertices.size() % 6, 0U);
  float lowest = 1e9f;
  float highest = -1e9f;
  for (std::size_t v = 0; v < mesh.vertices.size(); v += 6) {
    const Vec3f p(mesh.vertices[v], mesh.vertices[v + 1], mesh.vertices[v + 2]);
    const Vec3f n(mesh.vertices[v + 3], mesh.vertices[v + 4], mesh.vertices[v + 5]);
    const Vec3f out = Vec3f(p.x() - center.x(), p.y() - center.y(), 0.0f);
    const float distance = out.norm();
    const float rise = p.z() - center.z();
    lowest = std::min(lowest, rise);
    highest = std::max(highest, rise);
    EXPECT_GE(distance, 4.0f - 1e-4f);
    EXPECT_LE(distance, 5.0f + 1e-4f);
    EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
    EXPECT_LE(n.dot(out / distance), 1e-5f) << "the normal faces the axis";
    // On the quarter circle about (radius, curve), or on the wall beyond it.
    if (rise < 1.0f - 1e-4f) {
      EXPECT_NEAR(std::hypot(distance - 4.0f, rise - 1.0f), 1.0f, 1e-4f);
    } else {
      EXPECT_NEAR(distance, 5.0f, 1e-4f);
    }
    if (rise < 1e-6f) {
      EXPECT_NEAR(n.z(), 1.0f, 1e-6f) << "tangent to the plane where it leaves it";
    }
  }
  EXPECT_NEAR(lowest, 0.0f, 1e-6f);
  EXPECT_NEAR(highest, 6.0f, 1e-5f);
  // Closed round the axis: 64 columns of 9 quads (8 on the curve, 1 up the wall).
  EXPECT_EQ(mesh.indices.size(), 64U * 9U * 6U);
}

TEST(Cyclorama, EveryCameraStandsInsideAndSeesWallAboveEveryPicture) {
  DrawList list;
  list.ground_center = Vec3f(0.0f, 0.0f, 0.0f);
  Bounds subject;
  subject.add(Vec3f(-0.5f, -0.3f, 0.0f));
  subject.add(Vec3f(0.5f, 0.3f, 2.0f));
  std::vector<RenderCamera> cameras;
  for (int k = 0; k < 8; ++k) {  // an orbit of 6 m at 1.5 m, and one looking up at 20°
    const float angle = static_cast<float>(k) * std::numbers::pi_v<float> / 4.0f;
    RenderCamera camera;
    camera.position = Vec3f(6.0f * std::cos(angle), 6.0f * std::sin(angle), 1.5f);
    camera.look_at = Vec3f(0.0f, 0.0f, 1.5f + (k == 3 ? 6.0f * std::tan(0.349f) : 0.0f));
    camera.fov_degrees = 40.0f;
    cameras.push_back(camera);
  }
  fit_backdrop(subject, cameras, list);
  EXPECT_GE(list.backdrop_radius, 1.25f * 6.0f - 1e-4f);
  EXPECT_NEAR(list.backdrop_curve, list.backdrop_radius / 3.0f, 1e-5f);
  const float wall = list.backdrop_radius + list.backdrop_curve;
  for (const RenderCamera& camera : cameras) {
    // The ray through the top centre of the picture, to where it meets the wall's cylinder.
    const Vec3f sight = (camera.look_at - camera.position).normalized();
    const Vec3f right = sight.cross(camera.up).normalized();
    const Vec3f up = right.cross(sight);
    const float half = 0.5f * camera.fov_degrees * std::numbers::pi_v<float> / 180.0f;
    const Vec3f ray = (sight + std::tan(half) * up).normalized();
    const Eigen::Vector2f p(camera.position.x(), camera.position.y());
    const Eigen::Vector2f d(ray.x(), ray.y());
    // |p + t d| = wall, t > 0.
    const float a = d.squaredNorm();
    const float b = 2.0f * p.dot(d);
    const float c = p.squaredNorm() - wall * wall;
    ASSERT_LT(c, 0.0f) << "the camera is inside the wall";
    const float t = (-b + std::sqrt(b * b - 4.0f * a * c)) / (2.0f * a);
    EXPECT_LT(camera.position.z() + t * ray.z(), list.backdrop_height)
        << "the picture's top edge meets the wall below its top";
  }
}

TEST(Cyclorama, ASubjectWiderThanTheCamerasAreFarSetsTheRadius) {
  DrawList list;
  Bounds subject;
  subject.add(Vec3f(-3.0f, -4.0f, 0.0f));
  subject.add(Vec3f(3.0f, 4.0f, 1.0f));
  RenderCamera close;
  close.position = Vec3f(1.0f, 0.0f, 1.0f);
  close.look_at = Vec3f(0.0f, 0.0f, 0.5f);
  fit_backdrop(subject, {close}, list);
  EXPECT_NEAR(list.backdrop_radius, 10.0f, 1e-4f);  // the box's diagonal across the ground
}

}  // namespace
}  // namespace dinam
