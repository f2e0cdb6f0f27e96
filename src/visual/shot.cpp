#include "visual/shot.hpp"

#include <utility>

#include "visual/backdrop.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/simulated_frames.hpp"

namespace dinam {

Shot make_shot(const SceneDescription& scene, const Model& model, const SimulatedFrames& frames,
               std::vector<Image> textures) {
  Shot shot;
  shot.draw_list = make_draw_list(scene, model, drawn_bounds(frames.motion, frames.subject),
                                  std::move(textures));
  shot.cameras = frame_cameras(scene, model, frames);
  fit_backdrop(scene, frames.subject, shot.cameras, shot.draw_list);
  return shot;
}

}  // namespace dinam
