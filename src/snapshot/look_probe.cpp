#include "snapshot/look_probe.hpp"

#include <cmath>

namespace dinam {
namespace {

float changed(float channel) {
  return channel < 0.5f ? channel + kLookChange : channel - kLookChange;
}

void change_green(Vec3f& color) {
  color.y() = changed(color.y());
}

}  // namespace

DrawList with_changed_look(const DrawList& list, const std::vector<std::uint8_t>& chosen) {
  DrawList probe = list;
  const auto given = static_cast<Index>(chosen.size());
  // Whether point p, given or made from given ones (by its first source), is the object's.
  const auto of_object = [&](Index p) {
    if (p >= given) {
      p = list.derived.sources[static_cast<std::size_t>(list.derived.offsets[p - given])];
    }
    return chosen[static_cast<std::size_t>(p)] != 0;
  };
  for (std::size_t s = 0; s < probe.segment_color.size(); ++s) {
    if (of_object(list.segment_points[2 * s])) {
      change_green(probe.segment_color[s]);
    }
  }
  for (std::size_t p = 0; p < probe.point_color.size(); ++p) {
    if (of_object(static_cast<Index>(p))) {
      change_green(probe.point_color[p]);
    }
  }
  const auto step = static_cast<int>(std::lround(255.0f * kLookChange));
  for (const SurfaceBatch& batch : list.surfaces) {
    if (batch.texture < 0 || batch.triangles.empty() || !of_object(batch.triangles.front())) {
      continue;
    }
    Image& texture = probe.textures[static_cast<std::size_t>(batch.texture)];
    for (std::size_t i = 1; i < texture.rgba.size(); i += 4) {  // the green of each texel
      const int value = texture.rgba[i];
      texture.rgba[i] = static_cast<std::uint8_t>(value < 128 ? value + step : value - step);
    }
  }
  probe.revision = new_draw_list_revision();
  return probe;
}

}  // namespace dinam
