#pragma once
// What the renderer draws, in its own terms: segments between points, joints, a ground and a
// camera. render/ never sees springs or materials; app/ fills this from the model once, and each
// frame only the point positions change.
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct RenderCamera {
  Vec3f position{4.0f, -6.0f, 3.0f};
  Vec3f look_at{0.0f, 0.0f, 1.0f};
  Vec3f up{0.0f, 0.0f, 1.0f};
  float fov_degrees = 40.0f;  // vertical
};

struct DrawList {
  std::vector<Index> segment_points;  // (n_segments × 2) ids into the per-frame positions
  std::vector<float> segment_radius;  // (n_segments) m
  std::vector<Vec3f> segment_color;   // (n_segments) linear RGB
  std::vector<float> point_radius;    // (n_points) m; 0 draws no joint sphere
  std::vector<Vec3f> point_color;     // (n_points) linear RGB

  bool ground_visible = true;
  Vec3f ground_center = Vec3f::Zero();   // m, a point of the ground plane under the scene
  Vec3f ground_normal = Vec3f::UnitZ();  // unit
  float ground_half_size = 10.0f;  // m; the checker fades out towards this distance from the eye
  float ground_tile = 0.5f;        // m, checker size

  RenderCamera camera;
  Vec3f light_direction{0.35f, -0.45f, 0.82f};  // towards the light; normalised when drawn
};

}  // namespace dinam
