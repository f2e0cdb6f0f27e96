#pragma once
// How much memory a run will hold at its peak, by part, worked out from the built model before the
// run starts, and how much the machine can give; so that a scene too big for the machine is
// refused with the figures and what to do, instead of being killed by the system halfway.
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/byte_size.hpp"
#include "core/error.hpp"
#include "core/memory_budget.hpp"

namespace dinam {

struct Model;
struct SceneDescription;

// What the run does with the motion, which decides what it holds.
struct MemoryUse {
  int frames_held = 0;  // frames of positions kept at once (render: every frame simulated)
  bool energy = false;  // the energy report's per-kind force arrays
  int image_width = 0;  // pixels; 0 when nothing is drawn (dinam simulate)
  int image_height = 0;
  int instants_per_frame = 0;  // motion blur: positions held per frame besides the frame's own
};

// Bytes, by part. The peak is when the frames are all held and either the dynamics is running
// (with the settling phase's own state before it, and Newton's method's matrices) or the frames
// are being drawn.
struct MemoryEstimate {
  std::uint64_t program = 0;   // the program and its libraries, loaded
  std::uint64_t scene = 0;     // the scene's meshes as read
  std::uint64_t model = 0;     // the model's arrays (model.hpp), and the stepper's copy if any
  std::uint64_t dynamics = 0;  // the state, the contact's pairs and grids, and the settling's state
  std::uint64_t solver = 0;    // Newton's Hessian and factor: the implicit schemes', the settle's
  std::uint64_t frames = 0;    // the positions of every frame held
  std::uint64_t drawing = 0;   // OSMesa's buffers at the image size, the draw list, one PNG

  std::uint64_t peak() const;
  std::string summary() const;  // "1.2 GB: model 0.3 GB, frames 0.8 GB, …"
};

MemoryEstimate estimate_memory(const SceneDescription& scene, const Model& model,
                               const MemoryUse& use);

// Bytes of the state's arrays as make_state allocates them for `model` (dynamics/integrator.hpp),
// before any step has split the work between the threads or found a contact pair.
std::uint64_t made_state_bytes(const Model& model, bool energy);

// Throws UserError naming the scene, the estimate by part, the budget and what to do, when the
// estimate passes the budget and `force` is off; at `frames_key` (the scene's `duration`, when the
// frames held are the whole run's) when the frames are the largest part.
void refuse_if_over_budget(const std::filesystem::path& scene_path, const FileLoc& frames_key,
                           const MemoryEstimate& estimate, const MemoryBudget& budget, bool force);

}  // namespace dinam
