#pragma once
// Whether a snapshot's limits see each object it draws. An object a few pixels wide (a rope, a
// wire seen from afar) covers so few pixels that a change of its whole look stays within the
// share of differing pixels a comparison allows, and passes. At --update, `dinam snapshot` draws
// each golden frame again with one object's look changed by a set amount, object by object, and
// compares each with the golden under the frame's limits: a pass there means the goldens cannot
// catch such a change of that object, and it says so.
#include <cstdint>
#include <vector>

#include "render/draw_list.hpp"

namespace dinam {

// How much the probe moves the green of an object's colours: 0.13 of the full range, in linear
// RGB for colours (as a rope's green going from 0.58 to 0.45) and in the encoded values for a
// texture's texels, towards the far end of the range, so always by this much. One channel, the
// one the eye is most sensitive to, so that the probe is a modest change of hue, the kind a
// snapshot is kept to catch, not a repaint.
inline constexpr float kLookChange = 0.13f;

// `list` with the look of one object changed: the green of its wires', joints' and surfaces'
// colours and of every texel of its textures moved by kLookChange. The object is the points of
// the frame marked in `chosen` (one flag a point a frame gives), with what is made from them (a
// subdivided surface's points, the segments from them, the textures of surfaces of them). The
// ground, the sky and the other objects are left as they were, and the list gets a new revision
// so that a renderer uploads the new colours.
DrawList with_changed_look(const DrawList& list, const std::vector<std::uint8_t>& chosen);

}  // namespace dinam
