#pragma once
// The camera of every frame, and of every instant a blurred frame averages: fixed, framing the
// whole motion (auto: it does not jump), following an object's centroid, along a path through
// keys, or around an orbit.
#include <vector>

#include "render/draw_list.hpp"

namespace dinam {

struct Model;
struct SceneDescription;
struct SimulatedFrames;

struct FrameCameras {
  std::vector<RenderCamera> frames;    // (frames held)
  std::vector<RenderCamera> instants;  // (frames held × instants per frame); empty without blur
};

FrameCameras frame_cameras(const SceneDescription& scene, const Model& model,
                           const SimulatedFrames& frames);

}  // namespace dinam
