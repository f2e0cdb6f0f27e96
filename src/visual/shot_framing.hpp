#pragma once
// How a frame shows what it draws: where the drawn subject (every wire, joint and surface; not
// the ground) lies in the picture, and whether that makes a shot — the whole subject inside the
// frame, large enough to read. `dinam snapshot --framing` checks it on the frames it compares.
#include <cstdint>
#include <string>
#include <vector>

#include "render/draw_list.hpp"

namespace dinam {

// The picture-space box of the subject, as fractions of the picture's width (from the left) and
// height (from the top): 0 … 1 is inside. A wire counts with its drawn radius.
struct PictureExtent {
  float left = 0.0f;
  float right = 0.0f;
  float top = 0.0f;
  float bottom = 0.0f;
  bool empty = true;    // nothing drawn
  bool behind = false;  // some of it at or behind the eye's plane: not in the picture at all

  float width() const { return right - left; }
  float height() const { return bottom - top; }
};

// The extent of `list` drawn at `positions` (the frame's points, n_given) from `camera` in a
// picture of `aspect` = width / height. A subdivided surface's points are means of the frame's
// points, which bound them, so those count for it; torn bars and triangles (hidden,
// visual/torn_drawing.hpp) do not count.
PictureExtent picture_extent(const DrawList& list, const std::vector<Vec3f>& positions,
                             const RenderCamera& camera, float aspect);

// How thick wires show: the drawn diameter of the median wire of `list` at `positions` (of those
// whose first point `chosen` marks, where it is not empty), as a fraction of the picture's height;
// 0 where it draws no such wire. A snapshot uses it to say why a thin object escapes its
// comparison (snapshot/look_probe.hpp).
float median_wire_width(const DrawList& list, const std::vector<Vec3f>& positions,
                        const RenderCamera& camera, const std::vector<std::uint8_t>& chosen = {});

// What is wrong with the shot, in words ("" when nothing): a side where the frame cuts the
// subject (by more than `slack` of the picture, which the anti-aliased edge of a wire grazing it
// may take), or a subject spanning less than `min_fill` of both the width and the height.
std::string framing_problem(const PictureExtent& extent, float min_fill, float slack = 0.002f);

}  // namespace dinam
