#pragma once
// Where the camera stands: pure functions of the scene's bounds or an object's motion, so that
// framing is tested without any drawing.
#include <limits>
#include <vector>

#include "render/draw_list.hpp"

namespace dinam {

struct Bounds {
  Vec3f min = Vec3f::Constant(std::numeric_limits<float>::max());
  Vec3f max = Vec3f::Constant(std::numeric_limits<float>::lowest());

  void add(const Vec3f& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return (min.array() > max.array()).any(); }
  Vec3f center() const { return 0.5f * (min + max); }
  float radius() const { return 0.5f * (max - min).norm(); }
};

// A camera looking along `view_direction` (from the eye towards the scene) at the centre of
// `box`, just far enough that each of the box's eight corners projects inside the picture
// (`aspect` = width / height) with `margin` (1.08 = 8 % room): tighter than the bounding sphere,
// which leaves a flat or long subject small.
RenderCamera frame_box(const Bounds& box, const Vec3f& view_direction, const Vec3f& up,
                       float fov_degrees, float aspect, float margin = 1.08f);

// A camera that keeps `offset` (eye minus target) from the centroid of `points` in `positions`.
RenderCamera follow_points(const std::vector<Vec3f>& positions, const std::vector<Index>& points,
                           const Vec3f& offset, const Vec3f& up, float fov_degrees);

}  // namespace dinam
