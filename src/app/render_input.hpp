#pragma once
// What `render` and `render --preview` draw from: the scene as the command line changes it, its
// model, and every frame's positions, simulated or read from a motion cache. Everything that can
// be wrong with the input is found here, before the first file is written.
#include <optional>
#include <vector>

#include "app/commands.hpp"
#include "cache/motion_cache.hpp"
#include "core/image.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "run/frame_range.hpp"
#include "run/frame_source.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

class EnergyCsv;

struct RenderInput {
  SceneDescription scene;                       // with --size and --movie applied
  MovieFormat scene_movie = MovieFormat::kMp4;  // the scene's own, for `dinam movie` later
  std::vector<int> frames;  // the frames to draw, ascending (--frames 1,5,10-20, or every one)
  FrameRange range;         // from the first of them to the last
  std::optional<MotionCache> cache;  // --cache: the motion is read, not simulated
  Model model;
  std::optional<TimeStep> timestep;  // when simulating
  std::vector<Image> textures;       // every object's, read (a damaged PNG is a scene error)
};

// Reads the scene and applies `options` (and `adjust`, which may change the scene before its
// model is built); checks the cache against it, and refuses a run over the memory or run-time
// budget (unless --force). Throws UserError for bad input.
RenderInput read_render_input(const RenderOptions& options,
                              void (*adjust)(SceneDescription&) = nullptr);

// Every frame's positions: the cache's for the range, or the whole motion simulated (the whole
// motion frames the camera, the ground and the shadows, whichever frames are drawn), with a
// progress line and `energy` written each frame when given.
SimulatedFrames render_motion(const RenderInput& input, bool quiet, EnergyCsv* energy);

}  // namespace dinam
