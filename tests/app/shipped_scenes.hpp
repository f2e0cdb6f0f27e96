#pragma once
// What the tests of the shipped scenes share: loading one by name and simulating every frame.
#include <filesystem>
#include <functional>
#include <string>

#include "run/frame_source.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"

namespace dinam::test {

inline SceneDescription shipped(const std::string& name) {
  return read_scene(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes" / (name + ".yaml"));
}

// Every frame of a scene at its own time step.
inline SimulatedFrames simulate_scene(const SceneDescription& scene, const Model& model,
                                      bool track_energy = false,
                                      const std::function<void(int, const State&)>& on_frame = {}) {
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  return simulate_frames(model, timestep, scene.frame_count(), track_energy, on_frame);
}

}  // namespace dinam::test
