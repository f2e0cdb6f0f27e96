#include "snapshot/region_weights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/camera.hpp"

namespace dinam {
namespace {

// The pixel rectangle [x0, x1) × [y0, y1) a region covers, clamped to the picture; empty when
// x0 >= x1.
std::array<int, 4> covered(const SnapshotRegion& region, int width, int height,
                           const RenderCamera& camera) {
  std::array<int, 4> rect{0, 0, 0, 0};
  if (region.pixels) {
    rect = *region.pixels;
  } else {
    const Mat4f eye = eye_from_world(camera);
    float low_x = std::numeric_limits<float>::infinity();
    float low_y = low_x;
    float high_x = -low_x;
    float high_y = -low_x;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 world((corner & 1) != 0 ? region.box_high.x() : region.box_low.x(),
                       (corner & 2) != 0 ? region.box_high.y() : region.box_low.y(),
                       (corner & 4) != 0 ? region.box_high.z() : region.box_low.z());
      const Vec3f p = world.cast<float>();
      const Eigen::Vector4f in_eye = eye * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.0f);
      if (in_eye.z() >= 0.0f) {
        continue;  // behind the camera: no place in the picture
      }
      const Eigen::Vector2f pixel = pixel_from_world(camera, width, height, p);
      low_x = std::min(low_x, pixel.x());
      low_y = std::min(low_y, pixel.y());
      high_x = std::max(high_x, pixel.x());
      high_y = std::max(high_y, pixel.y());
    }
    if (!(low_x <= high_x)) {
      return rect;
    }
    const auto clamp_to = [](float v, int limit) {
      return static_cast<int>(std::clamp(v, 0.0f, static_cast<float>(limit)));
    };
    rect = {clamp_to(std::floor(low_x), width), clamp_to(std::floor(low_y), height),
            clamp_to(std::ceil(high_x) + 1.0f, width), clamp_to(std::ceil(high_y) + 1.0f, height)};
  }
  rect[0] = std::clamp(rect[0], 0, width);
  rect[2] = std::clamp(rect[2], 0, width);
  rect[1] = std::clamp(rect[1], 0, height);
  rect[3] = std::clamp(rect[3], 0, height);
  return rect;
}

}  // namespace

std::vector<float> region_weights(const std::vector<SnapshotRegion>& regions, int width, int height,
                                  const RenderCamera& camera) {
  if (regions.empty()) {
    return {};
  }
  std::vector<float> weights(static_cast<std::size_t>(width) * height, 1.0f);
  std::vector<std::uint8_t> ignored(weights.size(), 0);
  for (const SnapshotRegion& region : regions) {
    const std::array<int, 4> rect = covered(region, width, height, camera);
    for (int y = rect[1]; y < rect[3]; ++y) {
      for (int x = rect[0]; x < rect[2]; ++x) {
        const std::size_t p = static_cast<std::size_t>(y) * width + x;
        if (region.weight <= 0.0f) {
          ignored[p] = 1;
        } else {
          weights[p] = std::max(weights[p], region.weight);
        }
      }
    }
  }
  for (std::size_t p = 0; p < weights.size(); ++p) {
    if (ignored[p] != 0) {
      weights[p] = 0.0f;
    }
  }
  return weights;
}

}  // namespace dinam
