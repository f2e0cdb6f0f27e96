#pragma once
// The run split into its stages, each usable alone: simulate every frame's positions (or read
// them from a motion cache), decide the camera of each frame, then draw them through any Renderer
// (OSMesa, or a recording one in tests).
#include <filesystem>
#include <functional>
#include <vector>

#include "app/torn_drawing.hpp"
#include "core/image.hpp"
#include "dynamics/state.hpp"
#include "render/framing.hpp"
#include "render/renderer.hpp"

namespace dinam {

class MotionCache;
struct Model;
struct SceneDescription;
struct TimeStep;

// Node positions of consecutive frames first_frame, first_frame + 1, … (frame k at
// t = (k − 1)/fps), in single precision, and the bounds of the whole motion they belong to, which
// frame the camera, the ground and the shadows: so frames drawn in chunks are those of one run.
struct SimulatedFrames {
  int first_frame = 1;
  std::vector<std::vector<Vec3f>> positions;  // (frames held) × (n_nodes)
  Bounds motion;                              // every position of every frame of the motion
  Bounds subject;  // every frame's subject box (core/subject_box.hpp): what camera: auto frames
  double seconds = 0.0;                       // wall time spent simulating or reading
  SettleOutcome settled;                      // how the settling phase ended (simulated only)
  std::vector<TornBar> tears;                 // in the order they broke

  int last_frame() const { return first_frame + static_cast<int>(positions.size()) - 1; }
  const std::vector<Vec3f>& at(int frame) const {
    return positions[static_cast<std::size_t>(frame - first_frame)];
  }
};

// Runs the dynamics to frame `last`, calling `on_frame(frame, state)` at each frame's time.
// Throws Interrupted (command_support.hpp) at the next step after SIGINT or SIGTERM.
void run_dynamics(const Model& model, const TimeStep& timestep, int last, bool track_energy,
                  const std::function<void(int, const State&)>& on_frame);

// Runs the dynamics to frame `last`, holding frames 1 … last. `on_frame(frame, state)` is called
// once per frame (for energy reports and progress).
SimulatedFrames simulate_frames(const Model& model, const TimeStep& timestep, int last,
                                bool track_energy,
                                const std::function<void(int, const State&)>& on_frame = {});

// One line on how the settling phase ended, for the log: "" when there was none.
std::string settle_summary(const SettleOutcome& settled, double dt);

// Frames first … last from a cache, with the bounds of its whole motion.
SimulatedFrames cached_frames(const MotionCache& cache, int first, int last);

// The camera of every frame held: fixed, framing the whole motion (auto: it does not jump), or
// following an object's centroid.
std::vector<RenderCamera> frame_cameras(const SceneDescription& scene, const Model& model,
                                        const SimulatedFrames& frames);

// Draws frames first … last (all held), handing each picture to `on_image(frame, image)`;
// `cameras` are those of frame_cameras.
void draw_frames(Renderer& renderer, const DrawList& list, const SimulatedFrames& frames,
                 const std::vector<RenderCamera>& cameras, int first, int last,
                 const std::function<void(int, const Image&)>& on_image);

}  // namespace dinam
