#pragma once
// The frames of a run: simulate every frame's positions (or read them from a motion cache); the
// visual stage then decides the camera of each frame (visual/frame_cameras.hpp) and draws them
// through any Renderer (visual/frame_drawing.hpp: OSMesa, or a recording one in tests).
#include <filesystem>
#include <functional>
#include <vector>

#include "core/image.hpp"
#include "dynamics/state.hpp"
#include "render/framing.hpp"
#include "render/renderer.hpp"
#include "visual/frame_cameras.hpp"
#include "visual/simulated_frames.hpp"

namespace dinam {

class MotionCache;
struct Model;
struct MotionBlurDesc;
struct SceneDescription;
struct TimeStep;

// The instants a blurred frame averages, as whole steps from the frame's own step, ascending:
// `blur.samples` instants spread evenly over `blur.shutter` of the frame interval, centred on the
// frame (each at the step nearest its ideal time). Empty without blur.
std::vector<int> shutter_offsets(const MotionBlurDesc& blur, int steps_per_frame);

// Runs the dynamics to frame `last`, calling `on_frame(frame, state)` at each frame's time.
// With `shutter` (shutter_offsets), also `on_instant(frame, k, state)` at each frame's k-th
// instant: before t = 0 the structure is where it starts, and the last frame's shutter runs a
// little past it. Throws Interrupted (command_support.hpp) at the next step after SIGINT or
// SIGTERM.
void run_dynamics(const Model& model, const TimeStep& timestep, int last, bool track_energy,
                  const std::function<void(int, const State&)>& on_frame,
                  const std::vector<int>& shutter = {},
                  const std::function<void(int, int, const State&)>& on_instant = {});

// Runs the dynamics to frame `last`, holding frames 1 … last, and their instants for `blur`.
// `on_frame(frame, state)` is called once per frame (for energy reports and progress).
SimulatedFrames simulate_frames(const Model& model, const TimeStep& timestep, int last,
                                bool track_energy,
                                const std::function<void(int, const State&)>& on_frame = {},
                                const MotionBlurDesc* blur = nullptr);

// One line on how the settling phase ended, for the log: "" when there was none.
std::string settle_summary(const SettleOutcome& settled, double dt);

// Frames first … last from a cache, with the bounds of its whole motion, and their instants when
// `blur` asks for them (render_input.cpp has drawn without blur where the cache lacks them).
SimulatedFrames cached_frames(const MotionCache& cache, int first, int last,
                              const MotionBlurDesc* blur = nullptr);

}  // namespace dinam
