#pragma once
// A scene drawn from its model's rest positions with the scene's fixed camera: what the benchmarks
// that time drawing alone (no simulation) share.
#include <vector>

#include "model/model.hpp"
#include "render/draw_list.hpp"
#include "render/framing.hpp"
#include "scene/scene_description.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {

struct RestFrame {
  DrawList list;
  std::vector<Vec3f> positions;
  RenderCamera camera;
};

inline RestFrame rest_frame(const SceneDescription& scene, const Model& model) {
  RestFrame frame;
  positions_for_render(model.node_initial_x, frame.positions);
  Bounds bounds;
  for (const Vec3f& p : frame.positions) {
    bounds.add(p);
  }
  frame.list = make_draw_list(scene, model, bounds);
  frame.camera = {scene.camera.position.cast<float>(), scene.camera.look_at.cast<float>(),
                  Vec3f::UnitZ(), static_cast<float>(scene.camera.fov_degrees)};
  return frame;
}

}  // namespace dinam
