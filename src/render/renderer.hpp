#pragma once
// The renderer behind a small interface, so that what is drawn and how it is framed can be
// tested without OpenGL (tests use a recording implementation; the program uses OsmesaRenderer).
#include <span>
#include <vector>

#include "core/image.hpp"
#include "render/draw_list.hpp"

namespace dinam {

// One instant of a frame: the points where they are then, seen by the camera of then.
struct FrameSample {
  const std::vector<Vec3f>* positions = nullptr;  // (n_points)
  RenderCamera camera;
};

class Renderer {
 public:
  virtual ~Renderer() = default;
  // Draws `list` at each of `samples` (at least one) into `image`, averaged in linear light:
  // several instants within a shutter interval give motion blur.
  virtual void render(const DrawList& list, std::span<const FrameSample> samples, Image& image) = 0;

  // One instant: `list` with its points at `positions` (n_points) seen by `camera`.
  void render(const DrawList& list, const std::vector<Vec3f>& positions, const RenderCamera& camera,
              Image& image) {
    const FrameSample sample{&positions, camera};
    render(list, std::span<const FrameSample>(&sample, 1), image);
  }
};

}  // namespace dinam
