#include "render/camera_path.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace dinam {
namespace {

// Cubic Hermite between p0 (tangent m0) and p1 (tangent m1) over an interval of length h, at the
// fraction s of it; tangents are per unit time.
template <typename T>
T hermite(const T& p0, const T& m0, const T& p1, const T& m1, float h, float s) {
  const float s2 = s * s;
  const float s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * m1;
}

// The Catmull–Rom tangent of a key: the slope between its neighbours, zero at either end.
template <typename T, typename Get>
T tangent(const std::vector<CameraKey>& keys, std::size_t k, const Get& get, const T& zero) {
  if (k == 0 || k + 1 == keys.size()) {
    return zero;
  }
  const auto span = static_cast<float>(keys[k + 1].time - keys[k - 1].time);
  return (get(keys[k + 1]) - get(keys[k - 1])) / span;
}

}  // namespace

RenderCamera camera_on_path(const std::vector<CameraKey>& keys, double t, const Vec3f& up) {
  DINAM_CHECK(!keys.empty());
  RenderCamera camera;
  camera.up = up;
  const auto set = [&](const CameraKey& key) {
    camera.position = key.position;
    camera.look_at = key.look_at;
    camera.fov_degrees = key.fov_degrees;
    return camera;
  };
  if (t <= keys.front().time) {
    return set(keys.front());
  }
  if (t >= keys.back().time) {
    return set(keys.back());
  }
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), t,
                       [](double time, const CameraKey& key) { return time < key.time; });
  const auto k = static_cast<std::size_t>(after - keys.begin()) - 1;
  const CameraKey& a = keys[k];
  const CameraKey& b = keys[k + 1];
  const auto h = static_cast<float>(b.time - a.time);
  const auto s = static_cast<float>((t - a.time) / (b.time - a.time));
  const auto position = [](const CameraKey& key) { return key.position; };
  const auto look_at = [](const CameraKey& key) { return key.look_at; };
  const auto fov = [](const CameraKey& key) { return key.fov_degrees; };
  const Vec3f zero = Vec3f::Zero();
  camera.position = hermite(a.position, tangent(keys, k, position, zero), b.position,
                            tangent(keys, k + 1, position, zero), h, s);
  camera.look_at = hermite(a.look_at, tangent(keys, k, look_at, zero), b.look_at,
                           tangent(keys, k + 1, look_at, zero), h, s);
  camera.fov_degrees = hermite(a.fov_degrees, tangent(keys, k, fov, 0.0f), b.fov_degrees,
                               tangent(keys, k + 1, fov, 0.0f), h, s);
  return camera;
}

RenderCamera orbit_camera(const Vec3f& center, float radius, float height, float angle,
                          const Vec3f& up, float fov_degrees) {
  const Vec3f axis = up.normalized();
  // A fixed direction across the axis: world x, or y where the axis is near x.
  const Vec3f seed = std::abs(axis.x()) < 0.9f ? Vec3f::UnitX() : Vec3f::UnitY();
  const Vec3f across = (seed - seed.dot(axis) * axis).normalized();
  const Vec3f side = axis.cross(across);
  RenderCamera camera;
  camera.position =
      center + radius * (std::cos(angle) * across + std::sin(angle) * side) + height * axis;
  camera.look_at = center;
  camera.up = axis;
  camera.fov_degrees = fov_degrees;
  return camera;
}

}  // namespace dinam
