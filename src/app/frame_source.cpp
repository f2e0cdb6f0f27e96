#include "app/frame_source.hpp"

#include <chrono>

#include "app/draw_list_from_model.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "render/framing.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

SimulatedFrames simulate_frames(const Model& model, const TimeStep& timestep, int last,
                                bool track_energy,
                                const std::function<void(int, const State&)>& on_frame) {
  const auto start = std::chrono::steady_clock::now();
  SimulatedFrames frames;
  frames.positions.resize(static_cast<std::size_t>(last));
  State state = initial_state(model, timestep.dt, {}, track_energy);
  for (int frame = 1; frame <= last; ++frame) {
    if (frame > 1) {
      for (int s = 0; s < timestep.steps_per_frame; ++s) {
        step(model, timestep.dt, {}, state);
      }
    }
    positions_for_render(state.x, frames.positions[static_cast<std::size_t>(frame - 1)]);
    if (on_frame) {
      on_frame(frame, state);
    }
  }
  frames.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return frames;
}

std::vector<RenderCamera> frame_cameras(const SceneDescription& scene, const Model& model,
                                        const SimulatedFrames& frames) {
  const CameraDesc& desc = scene.camera;
  const Vec3f up = desc.up.cast<float>();
  const auto fov = static_cast<float>(desc.fov_degrees);
  std::vector<RenderCamera> cameras;
  cameras.reserve(frames.positions.size());
  switch (desc.mode) {
    case CameraDesc::Mode::kFixed: {
      const RenderCamera camera{desc.position.cast<float>(), desc.look_at.cast<float>(), up, fov};
      cameras.assign(frames.positions.size(), camera);
      break;
    }
    case CameraDesc::Mode::kAuto: {
      const Bounds bounds = motion_bounds(frames.positions);
      const float aspect =
          static_cast<float>(scene.image_width) / static_cast<float>(scene.image_height);
      cameras.assign(frames.positions.size(),
                     frame_bounds(bounds, desc.direction.cast<float>(), up, fov, aspect));
      break;
    }
    case CameraDesc::Mode::kFollow: {
      std::vector<Index> points;
      for (const ModelObject& object : model.objects) {
        if (object.name == desc.follow) {
          for (Index i = 0; i < object.node_count; ++i) {
            points.push_back(object.first_node + i);
          }
        }
      }
      for (const auto& positions : frames.positions) {
        cameras.push_back(follow_points(positions, points, desc.offset.cast<float>(), up, fov));
      }
      break;
    }
  }
  return cameras;
}

void draw_frames(Renderer& renderer, const DrawList& list, const SimulatedFrames& frames,
                 const std::vector<RenderCamera>& cameras, int first, int last,
                 const std::function<void(int, const Image&)>& on_image) {
  Image image;
  for (int frame = first; frame <= last; ++frame) {
    const auto k = static_cast<std::size_t>(frame - 1);
    renderer.render(list, frames.positions[k], cameras[k], image);
    on_image(frame, image);
  }
}

}  // namespace dinam
