#include "render/framing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dinam {

RenderCamera frame_bounds(const Bounds& bounds, const Vec3f& view_direction, const Vec3f& up,
                          float fov_degrees, float aspect, float margin) {
  const float to_radians = std::numbers::pi_v<float> / 180.0f;
  const float half_vertical = 0.5f * fov_degrees * to_radians;
  const float half_horizontal = std::atan(std::tan(half_vertical) * aspect);
  const float half_angle = std::min(half_vertical, half_horizontal);
  const float radius = std::max(bounds.radius(), 1e-3f) * margin;
  const float distance = radius / std::sin(half_angle);
  RenderCamera camera;
  camera.look_at = bounds.center();
  camera.position = camera.look_at - distance * view_direction.normalized();
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
