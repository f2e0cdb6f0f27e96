#include "app/frame_source.hpp"

#include <chrono>

#include "app/command_support.hpp"
#include "app/draw_list_from_model.hpp"
#include "app/torn_drawing.hpp"
#include "cache/motion_cache.hpp"
#include "core/subject_box.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

void run_dynamics(const Model& model, const TimeStep& timestep, int last, bool track_energy,
                  const std::function<void(int, const State&)>& on_frame) {
  State state = initial_state(model, timestep.dt, {}, track_energy);
  for (int frame = 1; frame <= last; ++frame) {
    if (frame > 1) {
      for (int s = 0; s < timestep.steps_per_frame; ++s) {
        stop_if_asked();  // within a step of SIGINT or SIGTERM, however long a frame takes
        step(model, timestep.dt, {}, state);
      }
    }
    on_frame(frame, state);
  }
}

SimulatedFrames simulate_frames(const Model& model, const TimeStep& timestep, int last,
                                bool track_energy,
                                const std::function<void(int, const State&)>& on_frame) {
  const auto start = Clock::now();
  SimulatedFrames frames;
  frames.positions.resize(static_cast<std::size_t>(last));
  run_dynamics(model, timestep, last, track_energy, [&](int frame, const State& state) {
    positions_for_render(state.x, frames.positions[static_cast<std::size_t>(frame - 1)]);
    if (frame == 1) {
      frames.settled = state.settled;
    }
    record_tears(model, state, frame, frames.tears);
    if (on_frame) {
      on_frame(frame, state);
    }
  });
  frames.motion = motion_bounds(frames.positions);
  for (const std::vector<Vec3f>& positions : frames.positions) {
    Vec3f lo;
    Vec3f hi;
    subject_box(positions, lo, hi);
    frames.subject.add(lo);
    frames.subject.add(hi);
  }
  frames.seconds = seconds_since(start);
  return frames;
}

std::string settle_summary(const SettleOutcome& settled, double dt) {
  if (!settled.ran) {
    return "";
  }
  return fmt::format(
      "settled under gravity in {:g} s ({} steps: {} overdamped, then {} of kinetic damping with "
      "{} restarts from rest); the largest out-of-balance force is {:.2g} of a node's weight",
      static_cast<double>(settled.steps) * dt, settled.steps, settled.viscous_steps,
      settled.steps - settled.viscous_steps, settled.restarts, settled.residual);
}

SimulatedFrames cached_frames(const MotionCache& cache, int first, int last) {
  const auto start = Clock::now();
  SimulatedFrames frames;
  frames.first_frame = first;
  frames.positions = cache.read_frames(first, last);
  for (const CacheTear& tear : cache.manifest().tears) {
    frames.tears.push_back({tear.frame, tear.n0, tear.n1});
  }
  for (const FrameBounds& bounds : cache.manifest().frame_bounds) {
    frames.motion.add(bounds.min);
    frames.motion.add(bounds.max);
    frames.subject.add(bounds.subject_min);
    frames.subject.add(bounds.subject_max);
  }
  frames.seconds = seconds_since(start);
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
      const float aspect =
          static_cast<float>(scene.image_width) / static_cast<float>(scene.image_height);
      cameras.assign(frames.positions.size(),
                     frame_box(frames.subject, desc.direction.cast<float>(), up, fov, aspect));
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
  DINAM_CHECK(first >= frames.first_frame && last <= frames.last_frame());
  Image image;
  // With tears, a copy of the list loses each torn bar from the first frame that shows it broken.
  DrawList torn;
  if (!frames.tears.empty()) {
    torn = list;
  }
  std::size_t shown = 0;
  for (int frame = first; frame <= last; ++frame) {
    const std::size_t before = shown;
    while (shown < frames.tears.size() && frames.tears[shown].frame <= frame) {
      hide_torn_bar(frames.tears[shown++], torn);
    }
    torn.revision += shown > before ? 1 : 0;
    renderer.render(frames.tears.empty() ? list : torn, frames.at(frame),
                    cameras[static_cast<std::size_t>(frame - frames.first_frame)], image);
    on_image(frame, image);
  }
}

}  // namespace dinam
