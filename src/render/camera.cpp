#include "render/camera.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace dinam {

Mat4f eye_from_world(const RenderCamera& camera) {
  const Vec3f forward = (camera.look_at - camera.position).normalized();
  const Vec3f right = forward.cross(camera.up).normalized();
  const Vec3f up = right.cross(forward);
  Mat4f m = Mat4f::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m(0, 3) = -right.dot(camera.position);
  m(1, 3) = -up.dot(camera.position);
  m(2, 3) = forward.dot(camera.position);
  return m;
}

Mat4f clip_from_eye(float fov_degrees, float aspect, float near_plane, float far_plane) {
  const float f = 1.0f / std::tan(0.5f * fov_degrees * std::numbers::pi_v<float> / 180.0f);
  Mat4f m = Mat4f::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2.0f * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1.0f;
  return m;
}

Eigen::Vector2f pixel_from_world(const RenderCamera& camera, int width, int height,
                                 const Vec3f& world) {
  const Mat4f clip_from_world =
      clip_from_eye(camera.fov_degrees, static_cast<float>(width) / static_cast<float>(height),
                    0.01f, 100.0f) *
      eye_from_world(camera);
  const Eigen::Vector4f clip = clip_from_world * world.homogeneous();
  const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
  return {(ndc.x() * 0.5f + 0.5f) * static_cast<float>(width),
          (0.5f - ndc.y() * 0.5f) * static_cast<float>(height)};
}

}  // namespace dinam
