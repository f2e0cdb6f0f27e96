#pragma once
// The run split into its stages, each usable alone: simulate every frame's positions, decide the
// camera of each frame, then draw them through any Renderer (OSMesa, or a recording one in tests).
#include <filesystem>
#include <functional>
#include <vector>

#include "core/image.hpp"
#include "dynamics/state.hpp"
#include "render/renderer.hpp"

namespace dinam {

struct Model;
struct SceneDescription;
struct TimeStep;

// Node positions of frames 1 … last (frame k at t = (k − 1)/fps), in single precision.
struct SimulatedFrames {
  std::vector<std::vector<Vec3f>> positions;  // (last) × (n_nodes)
  double seconds = 0.0;                       // wall time spent simulating
};

// Runs the dynamics to frame `last`. `on_frame(frame, state)` is called once per frame (for
// energy reports).
SimulatedFrames simulate_frames(const Model& model, const TimeStep& timestep, int last,
                                bool track_energy,
                                const std::function<void(int, const State&)>& on_frame = {});

// The camera of every frame: fixed, framing the motion of all frames (auto: it does not jump),
// or following an object's centroid.
std::vector<RenderCamera> frame_cameras(const SceneDescription& scene, const Model& model,
                                        const SimulatedFrames& frames);

// Draws frames first … last, handing each picture to `on_image(frame, image)`.
void draw_frames(Renderer& renderer, const DrawList& list, const SimulatedFrames& frames,
                 const std::vector<RenderCamera>& cameras, int first, int last,
                 const std::function<void(int, const Image&)>& on_image);

}  // namespace dinam
