#pragma once
// Cameras that move by themselves: along a path through keys, or around an orbit. Pure functions
// of time, so that the motion is tested without drawing.
#include <vector>

#include "render/draw_list.hpp"

namespace dinam {

// Where the eye is at a time, what it looks at, and its vertical field of view.
struct CameraKey {
  double time = 0.0;  // s
  Vec3f position = Vec3f::Zero();
  Vec3f look_at = Vec3f::Zero();
  float fov_degrees = 40.0f;
};

// The camera at time `t` on a smooth path through `keys` (at increasing times): position, look-at
// point and field of view each follow a cubic Hermite curve with Catmull–Rom tangents scaled to
// the keys' times, so the motion has no kinks; the tangent is zero at the first and the last key,
// so the camera eases in and out. It holds the first key before it and the last after it.
RenderCamera camera_on_path(const std::vector<CameraKey>& keys, double t, const Vec3f& up);

// A camera at horizontal distance `radius` from `center` and `height` above it (along `up`),
// `angle` radians around `up` from a fixed direction across it, looking at `center`.
RenderCamera orbit_camera(const Vec3f& center, float radius, float height, float angle,
                          const Vec3f& up, float fov_degrees);

}  // namespace dinam
