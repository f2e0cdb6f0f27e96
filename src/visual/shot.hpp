#pragma once
// A run's shot: what is drawn of the model (the draw list, sized on the motion, with the
// cyclorama fitted round every camera) and from where (every frame's and instant's camera).
// render, preview and snapshot all draw through one.
#include <vector>

#include "core/image.hpp"
#include "render/draw_list.hpp"
#include "visual/frame_cameras.hpp"

namespace dinam {

struct Model;
struct SceneDescription;
struct SimulatedFrames;

struct Shot {
  DrawList draw_list;
  FrameCameras cameras;
};

// `textures` as read_textures (visual/draw_list_from_model.hpp) read them.
Shot make_shot(const SceneDescription& scene, const Model& model, const SimulatedFrames& frames,
               std::vector<Image> textures);

}  // namespace dinam
