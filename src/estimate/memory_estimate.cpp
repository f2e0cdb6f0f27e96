#include "estimate/memory_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>

#include "core/error.hpp"
#include "dynamics/contact/contact_grid.hpp"
#include "dynamics/contact/object_contact_state.hpp"
#include "dynamics/force_kinds.hpp"
#include "estimate/implicit_cost.hpp"
#include "estimate/integrator_estimates.hpp"
#include "estimate/solver_memory.hpp"
#include "model/model.hpp"
#include "model/model_arrays.hpp"
#include "scene/scene_description.hpp"
#include "stepping/stepper_kind.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

// The figures that are not counted from the model were measured as peak resident memory
// (/usr/bin/time -f %M, Debian 12, Mesa 22.3 llvmpipe); bench/notes/performance.md has the runs.
//  - `dinam info` and `dinam simulate` of a rope of two bars: 70 MB, the program, its libraries
//    and their start-up (`python3 bench/estimate_check.py` found every small run 8–10 % over an
//    estimate that took 64 MB, what `dinam --version` alone holds).
constexpr std::uint64_t kProgramBytes = 70'000'000;
//  - OSMesa's context, llvmpipe's threads and compiled shaders, beside the per-pixel buffers:
//    a 121-node scene drawn at 640×360, 1920×1080 and 3840×2160 took 61, 155 and 473 MB over
//    `info`, i.e. 49 MB + 51 bytes a pixel with 4 samples, of which the shadow map is 17 MB.
constexpr std::uint64_t kRendererBytes = 32'000'000;
//  - Per pixel: OSMesa's RGBA buffer and its depth, llvmpipe's resolve target, the picture read
//    back and the frame writer's copy for PNG. The frame targets (render/frame_targets.hpp) are
//    made as the frames need them:
//     - a frame of one instant without occlusion: a multisampled RGBA8 colour and a 24-bit
//       depth, 8 bytes a sample;
//     - occlusion or motion blur: a half-float colour (8) and a depth (4) texture and the
//       occlusion at a quarter of the pixels, 13 bytes a pixel; with blur, the single-float sum
//       of the instants besides (16);
//     - a frame of one instant with occlusion: besides, a multisampled half-float colour and
//       depth, 12 bytes a sample.
constexpr std::uint64_t kBytesPerPixel = 20;
constexpr std::uint64_t kDirectBytesPerPixelSample = 8;
constexpr std::uint64_t kLinearBytesPerPixel = 13;
constexpr std::uint64_t kSumBytesPerPixel = 16;
constexpr std::uint64_t kLinearBytesPerPixelSample = 12;
constexpr std::uint64_t kBytesPerShadowTexel = 4;  // GL_DEPTH_COMPONENT24

// A std::vector of small vectors (mesh faces and lines) costs its header and a heap block each.
constexpr std::uint64_t kLoopBytes = sizeof(std::vector<Index>) + 16;

template <typename T>
std::uint64_t bytes_of(const std::vector<T>& array) {
  return static_cast<std::uint64_t>(array.capacity()) * sizeof(T);
}

std::uint64_t scene_bytes(const SceneDescription& scene) {
  std::uint64_t bytes = 0;
  for (const ObjectDesc& object : scene.objects) {
    const RawMesh& mesh = object.mesh;
    bytes += bytes_of(mesh.vertices) + bytes_of(mesh.uvs) + bytes_of(object.pin_motion.track);
    for (const auto* loops : {&mesh.faces, &mesh.lines}) {
      for (const std::vector<Index>& loop : *loops) {
        bytes += kLoopBytes + bytes_of(loop);
      }
    }
  }
  return bytes;
}

// Every array of model.hpp, as allocated (model_arrays.hpp lists them).
std::uint64_t model_bytes(const Model& model) {
  std::uint64_t bytes = 0;
  for_each_model_array(model,
                       [&](std::string_view, const auto& array) { bytes += bytes_of(array); });
  return bytes;
}

}  // namespace

std::uint64_t made_state_bytes(const Model& model, bool energy) {
  const auto nodes = static_cast<std::uint64_t>(model.node_count());
  const auto bars = static_cast<std::uint64_t>(model.bar_count());
  std::uint64_t bytes = nodes * 5 * sizeof(Vec3);  // x, velocity, force, x_next, v_next
  if (model.bars_are_constraints()) {  // each bar's multiplier and its projection's record
    bytes += bars * (sizeof(double) + sizeof(BarProjection));
  }
  for (const ForceKind* kind : kForceKinds) {  // each kind's own arrays
    bytes += kind->state_bytes != nullptr ? kind->state_bytes(model, energy) : 0;
  }
  if (energy) {
    bytes += nodes * 6 * sizeof(Vec3);  // the energy workspace's per-kind forces and v_whole
  }
  if (model.can_tear()) {  // a broken flag per spring and face, and the list of broken bars
    std::uint64_t springs = 0;
    for (const SpringKind* kind : kSpringKinds) {
      springs += static_cast<std::uint64_t>(kind->count(model));
    }
    bytes += springs + static_cast<std::uint64_t>(model.face_count()) + bars * sizeof(Index);
  }
  return bytes;
}

namespace {

// Contact pairs, which grow with what touches: a guess of two candidates and one touching pair
// (kept twice, for friction's history) for each node of the contact, about what a cloth resting
// on itself or on another holds.
constexpr std::uint64_t kPairBytesPerContactNode =
    2 * sizeof(ContactCandidate) + 2 * sizeof(ContactPoint);

// state.hpp's arrays for this model: as make_state allocates them, and what the contact's search
// grows at its first: the pairs and the grids of bars and triangles. (The split of the work
// between the threads is a few runs of springs per thread, and negligible.)
std::uint64_t state_bytes(const Model& model, bool energy) {
  std::uint64_t bytes = made_state_bytes(model, energy);
  if (model.contact.enabled) {
    bytes += model.contact.points.size() * kPairBytesPerContactNode;
    bytes += (model.contact.bars.size() + model.contact.triangle_face.size()) *
             ContactGrid::bytes_per_box();
  }
  return bytes;
}

}  // namespace

std::uint64_t MemoryEstimate::peak() const {
  return program + scene + model + frames + std::max(dynamics + solver, drawing);
}

std::string MemoryEstimate::summary() const {
  std::string text =
      fmt::format("{}: program {}, meshes {}, model {}, dynamics {}", byte_size(peak()),
                  byte_size(program), byte_size(scene), byte_size(model), byte_size(dynamics));
  if (solver > 0) {
    text += fmt::format(", solver {}", byte_size(solver));
  }
  text += fmt::format(", frames {}", byte_size(frames));
  if (drawing > 0) {
    text += fmt::format(", drawing {}", byte_size(drawing));
  }
  return text;
}

MemoryEstimate estimate_memory(const SceneDescription& scene, const Model& model,
                               const MemoryUse& use) {
  MemoryEstimate estimate;
  estimate.program = kProgramBytes;
  estimate.scene = scene_bytes(scene);
  // Twice where the stepper steps a copy of its own (the implicit schemes' softened ground).
  estimate.model = model_bytes(model) * (stepper_kind(model).copies_model(model) ? 2 : 1);
  estimate.dynamics = state_bytes(model, use.energy);
  estimate.solver = integrator_estimate(stepper_kind(model)).workspace_bytes(model);
  if (model.settle.enabled) {
    // settle.cpp relaxes the model (no driving forces) in a state of its own, by Newton's method
    // where it converges (its matrices freed before the run's are made).
    estimate.dynamics += state_bytes(model, false);
    estimate.solver = std::max(estimate.solver, newton_bytes(model, hessian_factor_size(model)));
  }
  estimate.frames =
      static_cast<std::uint64_t>(std::max(use.frames_held, 0)) *
      static_cast<std::uint64_t>(1 + std::max(use.instants_per_frame, 0)) *
      (static_cast<std::uint64_t>(model.node_count()) * sizeof(Vec3f) + sizeof(std::vector<Vec3f>));
  if (use.image_width > 0 && use.image_height > 0) {
    const auto pixels =
        static_cast<std::uint64_t>(use.image_width) * static_cast<std::uint64_t>(use.image_height);
    const auto samples = static_cast<std::uint64_t>(std::max(scene.quality.samples, 1));
    const auto shadow =
        scene.quality.shadows ? static_cast<std::uint64_t>(scene.quality.shadow_resolution) : 0;
    // Which targets the frames need: a blurred scene's frames at rest are drawn as one instant.
    const bool occlusion = scene.quality.look.ambient_occlusion;
    const bool blur = scene.quality.motion_blur.enabled();
    std::uint64_t per_pixel = kBytesPerPixel;
    per_pixel += occlusion ? 0 : samples * kDirectBytesPerPixelSample;
    per_pixel += occlusion || blur ? kLinearBytesPerPixel : 0;
    per_pixel += blur ? kSumBytesPerPixel : 0;
    per_pixel += occlusion ? samples * kLinearBytesPerPixelSample : 0;
    estimate.drawing = kRendererBytes + pixels * per_pixel +
                       shadow * shadow * kBytesPerShadowTexel + draw_list_bytes(scene, model);
    if (blur) {  // the instants' shadow map, of half the resolution
      estimate.drawing += shadow * shadow / 4 * kBytesPerShadowTexel;
    }
  }
  return estimate;
}

void refuse_if_over_budget(const std::filesystem::path& scene_path, const FileLoc& frames_key,
                           const MemoryEstimate& estimate, const MemoryBudget& budget, bool force) {
  if (force || budget.source.empty() || estimate.peak() <= budget.bytes) {
    return;
  }
  // The advice that shrinks the largest part.
  const std::uint64_t mesh_parts =
      estimate.scene + estimate.model + estimate.dynamics + estimate.solver;
  std::string advice = estimate.solver >= estimate.dynamics + estimate.model
                           ? "use a coarser mesh, or 'integrator: central_difference', whose steps "
                             "hold no matrix"
                           : "use a coarser mesh";
  const bool frames_largest = estimate.frames >= mesh_parts && estimate.frames >= estimate.drawing;
  if (frames_largest && frames_key.known()) {
    throw_user_error(frames_key,
                     "this run's frames need about {} of the {} it needs in all ({}), more than "
                     "the {} available ({}); a shorter 'duration', or draw it in parts from a "
                     "motion cache (dinam simulate, then render --cache DIR --frames A-B: only "
                     "those frames are held), or pass --force to run it anyway",
                     byte_size(estimate.frames), byte_size(estimate.peak()), estimate.summary(),
                     byte_size(budget.bytes), budget.source);
  }
  if (frames_largest) {
    advice =
        "draw it in parts from a motion cache (dinam simulate, then render --cache DIR --frames "
        "A-B: only those frames are held)";
  } else if (estimate.drawing >= mesh_parts) {
    advice = "draw smaller pictures (--size, or fewer quality samples)";
  }
  throw_user_error({},
                   "{}: this run needs about {}, more than the {} available ({}); {}, or pass "
                   "--force to run it anyway",
                   scene_path.string(), estimate.summary(), byte_size(budget.bytes), budget.source,
                   advice);
}

}  // namespace dinam
