#include "visual/shot_framing.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace dinam {
namespace {

// A pinhole camera's picture coordinates, with the scale that turns a length at a depth into a
// fraction of the picture's height.
class PictureProjection {
 public:
  PictureProjection(const RenderCamera& camera, float aspect)
      : eye_(camera.position), aspect_(aspect) {
    forward_ = (camera.look_at - camera.position).normalized();
    right_ = forward_.cross(camera.up).normalized();
    up_ = right_.cross(forward_);
    tan_half_ = std::tan(0.5f * camera.fov_degrees * 3.14159265f / 180.0f);
  }

  // How much of the picture's height a length across the view at `p` spans; 0 behind the eye.
  float height_fraction(const Vec3f& p, float length) const {
    const float depth = (p - eye_).dot(forward_);
    return depth > 0.0f ? 0.5f * length / (depth * tan_half_) : 0.0f;
  }

  // Adds a sphere of `radius` at `p` to `extent`.
  void add(const Vec3f& p, float radius, PictureExtent& extent) const {
    const Vec3f d = p - eye_;
    const float depth = d.dot(forward_);
    if (depth <= radius) {
      extent.behind = true;
      return;
    }
    // Half the picture's height spans depth × tan(fov/2) at that depth.
    const float half_height = depth * tan_half_;
    const float x = 0.5f + 0.5f * d.dot(right_) / (half_height * aspect_);
    const float y = 0.5f - 0.5f * d.dot(up_) / half_height;
    const float r_y = 0.5f * radius / half_height;
    const float r_x = r_y / aspect_;
    if (extent.empty) {
      extent = PictureExtent{x - r_x, x + r_x, y - r_y, y + r_y, false, extent.behind};
      return;
    }
    extent.left = std::min(extent.left, x - r_x);
    extent.right = std::max(extent.right, x + r_x);
    extent.top = std::min(extent.top, y - r_y);
    extent.bottom = std::max(extent.bottom, y + r_y);
  }

 private:
  Vec3f eye_;
  Vec3f forward_;
  Vec3f right_;
  Vec3f up_;
  float aspect_;
  float tan_half_ = 1.0f;
};

}  // namespace

PictureExtent picture_extent(const DrawList& list, const std::vector<Vec3f>& positions,
                             const RenderCamera& camera, float aspect) {
  const PictureProjection projection(camera, aspect);
  PictureExtent extent;
  for (std::size_t s = 0; s < list.segment_radius.size(); ++s) {
    const float radius = std::abs(list.segment_radius[s]);
    if (radius == 0.0f) {  // torn (visual/torn_drawing.hpp)
      continue;
    }
    for (int end = 0; end < 2; ++end) {
      const auto point = static_cast<std::size_t>(list.segment_points[2 * s + end]);
      projection.add(positions[point], radius, extent);
    }
  }
  for (std::size_t p = 0; p < positions.size() && p < list.point_radius.size(); ++p) {
    if (list.point_radius[p] > 0.0f) {
      projection.add(positions[p], list.point_radius[p], extent);
    }
  }
  for (const SurfaceBatch& batch : list.surfaces) {
    for (std::size_t t = 0; t + 2 < batch.triangles.size(); t += 3) {
      const Index* corner = &batch.triangles[t];
      if (corner[0] == corner[1] && corner[1] == corner[2]) {  // torn: collapsed to a point
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        const auto point = static_cast<std::size_t>(corner[k]);
        if (point < positions.size()) {
          projection.add(positions[point], 0.0f, extent);
          continue;
        }
        // A subdivided surface's point: a mean of frame points, which bound it.
        const auto derived = static_cast<Index>(point - positions.size());
        for (Index j = list.derived.offsets[derived]; j < list.derived.offsets[derived + 1]; ++j) {
          projection.add(positions[static_cast<std::size_t>(list.derived.sources[j])], 0.0f,
                         extent);
        }
      }
    }
  }
  return extent;
}

float median_wire_width(const DrawList& list, const std::vector<Vec3f>& positions,
                        const RenderCamera& camera, const std::vector<std::uint8_t>& chosen) {
  const PictureProjection projection(camera, 1.0f);
  std::vector<float> widths;
  widths.reserve(list.segment_radius.size());
  for (std::size_t s = 0; s < list.segment_radius.size(); ++s) {
    const float radius = std::abs(list.segment_radius[s]);
    const auto first = static_cast<std::size_t>(list.segment_points[2 * s]);
    if (radius == 0.0f || (!chosen.empty() && chosen[first] == 0)) {  // torn, or not chosen
      continue;
    }
    const Vec3f middle =
        0.5f *
        (positions[first] + positions[static_cast<std::size_t>(list.segment_points[2 * s + 1])]);
    widths.push_back(projection.height_fraction(middle, 2.0f * radius));
  }
  if (widths.empty()) {
    return 0.0f;
  }
  const auto middle = widths.begin() + static_cast<std::ptrdiff_t>(widths.size() / 2);
  std::nth_element(widths.begin(), middle, widths.end());
  return *middle;
}

std::string framing_problem(const PictureExtent& extent, float min_fill, float slack) {
  if (extent.empty) {
    return "nothing is drawn";
  }
  if (extent.behind) {
    return "part of the subject is behind the camera";
  }
  std::vector<std::string> cut;
  if (extent.left < -slack) {
    cut.push_back(fmt::format("left ({:.0f} % of the width outside)", -100.0f * extent.left));
  }
  if (extent.right > 1.0f + slack) {
    cut.push_back(
        fmt::format("right ({:.0f} % of the width outside)", 100.0f * (extent.right - 1.0f)));
  }
  if (extent.top < -slack) {
    cut.push_back(fmt::format("top ({:.0f} % of the height outside)", -100.0f * extent.top));
  }
  if (extent.bottom > 1.0f + slack) {
    cut.push_back(
        fmt::format("bottom ({:.0f} % of the height outside)", 100.0f * (extent.bottom - 1.0f)));
  }
  if (!cut.empty()) {
    return fmt::format("the frame cuts the subject at the {}", fmt::join(cut, ", "));
  }
  if (std::max(extent.width(), extent.height()) < min_fill) {
    return fmt::format(
        "the subject spans {:.0f} % of the width and {:.0f} % of the height, under the {:.0f} % "
        "asked of one of them",
        100.0f * extent.width(), 100.0f * extent.height(), 100.0f * min_fill);
  }
  return "";
}

}  // namespace dinam
