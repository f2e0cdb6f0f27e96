#include "render/framing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace dinam {

RenderCamera frame_box(const Bounds& box, const Vec3f& view_direction, const Vec3f& up,
                       float fov_degrees, float aspect, float margin) {
  const float to_radians = std::numbers::pi_v<float> / 180.0f;
  const float tan_vertical = std::tan(0.5f * fov_degrees * to_radians);
  const float tan_horizontal = tan_vertical * aspect;
  const Vec3f forward = view_direction.normalized();
  Vec3f right = forward.cross(up);
  if (right.squaredNorm() < 1e-12f) {  // looking along `up`: any right angle will do
    right = forward.unitOrthogonal();
  }
  right.normalize();
  const Vec3f true_up = right.cross(forward);
  std::array<Vec3f, 8> corners;
  for (int c = 0; c < 8; ++c) {
    corners[static_cast<std::size_t>(c)] = {(c & 1) != 0 ? box.max.x() : box.min.x(),
                                            (c & 2) != 0 ? box.max.y() : box.min.y(),
                                            (c & 4) != 0 ? box.max.z() : box.min.z()};
  }
  // Start from the bounding sphere's distance, then a few times: centre the corners' picture and
  // move so that its larger half-extent, in units of the picture's, becomes 1 / margin.
  // Perspective makes each move slightly off; the passes converge on it (the tests check the
  // result).
  const float radius = std::max(box.radius(), 1e-3f);
  Vec3f target = box.center();
  float distance = radius / std::min(tan_vertical, tan_horizontal) + radius;
  for (int pass = 0; pass < 8; ++pass) {
    const Vec3f eye = target - distance * forward;
    float x_lo = 1e30f;
    float x_hi = -1e30f;
    float y_lo = 1e30f;
    float y_hi = -1e30f;
    for (const Vec3f& p : corners) {
      const Vec3f d = p - eye;
      const float depth = std::max(d.dot(forward), 1e-6f * radius);
      const float x = d.dot(right) / (depth * tan_horizontal);
      const float y = d.dot(true_up) / (depth * tan_vertical);
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, y);
    }
    // Centre: a shift at the target's depth moves the picture by shift / (distance tan).
    target += 0.5f * (x_lo + x_hi) * distance * tan_horizontal * right +
              0.5f * (y_lo + y_hi) * distance * tan_vertical * true_up;
    const float half_extent = 0.5f * std::max(x_hi - x_lo, y_hi - y_lo);
    // The nearest corner must stay in front of the eye.
    float nearest_ahead = 0.0f;
    for (const Vec3f& p : corners) {
      nearest_ahead = std::max(nearest_ahead, -(p - target).dot(forward));
    }
    distance = std::max(distance * half_extent * margin, nearest_ahead + 0.01f * radius);
  }
  RenderCamera camera;
  camera.look_at = target;
  camera.position = target - distance * forward;
  camera.up = up;
  camera.fov_degrees = fov_degrees;
  return camera;
}

RenderCamera follow_points(const std::vector<Vec3f>& positions, const std::vector<Index>& points,
                           const Vec3f& offset, const Vec3f& up, float fov_degrees) {
  Vec3f centroid = Vec3f::Zero();
  for (const Index p : points) {
    centroid += positions[p];
  }
  centroid /= static_cast<float>(std::max<std::size_t>(points.size(), 1));
  RenderCamera camera;
  camera.look_at = centroid;
  camera.position = centroid + offset;
  camera.up = up;
  camera.fov_degrees = fov_degrees;
  return camera;
}

}  // namespace dinam
