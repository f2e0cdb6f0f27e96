#pragma once
// The renderer behind a small interface, so that what is drawn and how it is framed can be
// tested without OpenGL (tests use a recording implementation; the program uses OsmesaRenderer).
#include <vector>

#include "core/image.hpp"
#include "render/draw_list.hpp"

namespace dinam {

class Renderer {
 public:
  virtual ~Renderer() = default;
  // Draws `list` with its points at `positions` (n_points) seen by `camera` into `image`.
  virtual void render(const DrawList& list, const std::vector<Vec3f>& positions,
                      const RenderCamera& camera, Image& image) = 0;
};

}  // namespace dinam
