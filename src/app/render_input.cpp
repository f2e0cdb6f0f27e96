#include "app/render_input.hpp"

#include <fmt/format.h>

#include <optional>
#include <string>

#include "app/command_support.hpp"
#include "core/error.hpp"
#include "core/thread_governor.hpp"
#include "estimate/memory_estimate.hpp"
#include "estimate/run_estimate.hpp"
#include "run/energy_csv.hpp"
#include "run/progress.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {

RenderInput read_render_input(const RenderOptions& options, void (*adjust)(SceneDescription&)) {
  RenderInput input;
  SceneDescription& scene = input.scene;
  scene = read_scene(options.scene);
  if (adjust != nullptr) {
    adjust(scene);
  }
  if (options.size) {
    parse_image_size(*options.size, scene.image_width, scene.image_height);
  }
  input.scene_movie = scene.movie;  // `dinam movie` makes it from chunks drawn without
  if (options.movie) {
    scene.movie = parse_movie_format(*options.movie);
  }
  if (options.frames) {
    input.frames = parse_frame_list(*options.frames, scene.frame_count());
  } else {
    for (int frame = 1; frame <= scene.frame_count(); ++frame) {
      input.frames.push_back(frame);
    }
  }
  input.range = {input.frames.front(), input.frames.back()};
  if (options.cache) {
    if (options.energy_csv) {
      throw_user_error({},
                       "--energy reports what the simulation did, and --cache simulates nothing; "
                       "ask 'dinam simulate --energy' for it (manifest.json and energy.csv)");
    }
    input.cache.emplace(*options.cache);
    input.cache->check_scene(scene);
    if (const std::optional<std::string> shortfall = input.cache->motion_blur_shortfall(scene)) {
      fmt::print(stderr, "{}: warning: {}\n", scene.source.string(), *shortfall);
      scene.quality.motion_blur = MotionBlurDesc{};
    }
  }
  input.model = build_model_telling_warnings(scene);
  const Model& model = input.model;
  if (input.cache) {
    input.cache->check_model(model);
  } else {
    input.timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  }
  // Every frame of the motion is held (or, from a cache, those drawn) until it is drawn.
  // With motion blur, a simulated frame holds its instants too.
  const int frames_held = input.cache ? input.range.count() : scene.frame_count();
  const MotionBlurDesc& blur = scene.quality.motion_blur;
  const int instants = blur.enabled() ? blur.samples : 0;
  refuse_if_over_budget(options.scene, input.cache ? FileLoc{} : scene.duration_loc,
                        estimate_memory(scene, model,
                                        {frames_held, options.energy_csv, scene.image_width,
                                         scene.image_height, instants}),
                        available_memory(), options.force);
  if (input.timestep) {
    refuse_if_too_long(scene, model, *input.timestep,
                       estimate_run(scene, model, *input.timestep, thread_policy().most),
                       options.force);
  }
  input.textures = read_textures(scene);
  return input;
}

SimulatedFrames render_motion(const RenderInput& input, bool quiet, EnergyCsv* energy) {
  const SceneDescription& scene = input.scene;
  if (input.cache) {
    return cached_frames(*input.cache, input.range.first, input.range.last,
                         &scene.quality.motion_blur);
  }
  Progress progress(scene.frame_count(), !quiet, "simulate");
  try {
    return simulate_frames(
        input.model, *input.timestep, scene.frame_count(), energy != nullptr,
        [&](int frame, const State& s) {
          stop_if_asked();
          if (energy != nullptr) {
            energy->write(s.energy_workspace.last);
          }
          progress.update(frame, fmt::format("t = {:.2f} s", s.time));
        },
        &scene.quality.motion_blur);
  } catch (const Interrupted& e) {
    progress.finish();
    throw Interrupted(e.signal(), "it was still simulating, so no frame was drawn");
  }
}

}  // namespace dinam
