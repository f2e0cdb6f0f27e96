// `dinam info`: the model summary, for a person or (--json) for a script such as the Slurm farm.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "app/memory_estimate.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {
namespace {

// What `render` and `simulate` of this scene will hold at their peaks.
struct MemoryFigures {
  MemoryEstimate render;
  MemoryEstimate simulate;
  MemoryBudget available;
};

MemoryFigures memory_figures(const SceneDescription& scene, const Model& model) {
  return {estimate_memory(scene, model,
                          {scene.frame_count(), false, scene.image_width, scene.image_height}),
          estimate_memory(scene, model, {2, false, 0, 0}), available_memory()};
}

long long steps_in_all(const SceneDescription& scene, const Model& model,
                       const TimeStep& timestep) {
  const long long settling =
      model.settle.enabled ? std::llround(model.settle.duration / timestep.dt) : 0;
  return static_cast<long long>(scene.frame_count()) * timestep.steps_per_frame + settling;
}

void print_json(const SceneDescription& scene, const Model& model, const TimeStep& timestep,
                Index pinned) {
  const MemoryFigures memory = memory_figures(scene, model);
  nlohmann::ordered_json objects = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < model.objects.size(); ++k) {
    const ModelObject& object = model.objects[k];
    const RawMesh& mesh = scene.objects[k].mesh;
    objects.push_back({{"name", object.name},
                       {"nodes", object.node_count},
                       {"bars", object.bar_count},
                       {"mesh_materials", element_names(mesh, MeshNameKind::kMaterial)},
                       {"mesh_groups", element_names(mesh, MeshNameKind::kGroup)}});
  }
  const nlohmann::ordered_json json = {
      {"scene", scene.source.string()},
      {"name", scene.name},
      {"objects", objects},
      {"nodes", model.node_count()},
      {"pinned_nodes", pinned},
      {"bars", model.bar_count()},
      {"bending_springs", model.bend_count()},
      {"torsion_springs", model.torsion_count()},
      {"total_mass_kg", model.total_mass()},
      {"stability_limit_s", timestep.critical},
      {"timestep_s", timestep.dt},
      {"steps_per_frame", timestep.steps_per_frame},
      {"fps", scene.fps},
      {"frame_count", scene.frame_count()},
      {"duration_s", scene.duration},
      {"settle_s", model.settle.enabled ? model.settle.duration : 0.0},
      {"settle_residual", model.settle.enabled ? model.settle.residual : 0.0},
      {"steps", steps_in_all(scene, model, timestep)},
      {"memory_render_bytes", memory.render.peak()},
      {"memory_simulate_bytes", memory.simulate.peak()},
      {"memory_available_bytes", memory.available.bytes},
      {"output", scene.output.string()},
      {"movie", movie_format_name(scene.movie)},
  };
  fmt::print("{}\n", json.dump(1));
}

void print_text(const SceneDescription& scene, const Model& model, const TimeStep& timestep,
                Index pinned) {
  const int frames = scene.frame_count();
  fmt::print("scene            {} ('{}')\n", scene.source.string(), scene.name);
  fmt::print("objects          {}\n", model.objects.size());
  for (std::size_t k = 0; k < model.objects.size(); ++k) {
    const ModelObject& object = model.objects[k];
    fmt::print("  {:<14} {} nodes, {} bars\n", object.name, object.node_count, object.bar_count);
    // The names a part can choose bars by (`mesh_material`, `mesh_group`).
    const RawMesh& mesh = scene.objects[k].mesh;
    for (const auto& [kind, label] : {std::pair{MeshNameKind::kMaterial, "materials"},
                                      std::pair{MeshNameKind::kGroup, "groups"}}) {
      const std::vector<std::string> names = element_names(mesh, kind);
      if (!names.empty()) {
        fmt::print("  {:<14} the mesh file's {}: {}\n", "", label, fmt::join(names, ", "));
      }
    }
  }
  fmt::print("nodes            {} ({} pinned)\n", model.node_count(), pinned);
  fmt::print("bars             {}\n", model.bar_count());
  fmt::print("springs          axial {}, bending {}, torsion {}\n", model.bar_count(),
             model.bend_count(), model.torsion_count());
  fmt::print("no torsion       {} bars (torsion off, or no usable reference neighbour)\n",
             model.bars_without_torsion);
  fmt::print("total mass       {:.6g} kg\n", model.total_mass());
  fmt::print("stability limit  {:.6g} s ((2/ω)(√(1+ζ²) − ζ), ω and ζ bounded from above)\n",
             timestep.critical);
  fmt::print("time step        {:.6g} s ({})\n", timestep.dt,
             timestep.automatic ? fmt::format("auto: at most {} × the limit", kAutoTimestepSafety)
                                : "from the scene, fitted to whole steps per frame");
  fmt::print("steps per frame  {}\n", timestep.steps_per_frame);
  const long long steps_to_last_frame =
      static_cast<long long>(frames - 1) * timestep.steps_per_frame;
  fmt::print("frames           {} at {:g} fps, t = 0 … {:g} s\n", frames, scene.fps,
             (frames - 1) / scene.fps);
  fmt::print("steps            {} over the {:g} s duration ({} up to the last frame)\n",
             steps_to_last_frame + timestep.steps_per_frame, scene.duration, steps_to_last_frame);
  if (model.settle.enabled) {
    fmt::print(
        "settling         before t = 0 under gravity alone, until the out-of-balance force on "
        "every node is below {:g} of its weight; at most {:g} s ({} steps)\n",
        model.settle.residual, model.settle.duration,
        std::llround(model.settle.duration / timestep.dt));
  }
  fmt::print("steps in all     {}{}\n", steps_in_all(scene, model, timestep),
             model.settle.enabled ? " at most (settling stops once it has converged)" : "");
  const MemoryFigures memory = memory_figures(scene, model);
  fmt::print("memory, render   about {} at {}×{}\n", memory.render.summary(), scene.image_width,
             scene.image_height);
  fmt::print("memory, simulate about {}\n", memory.simulate.summary());
  if (!memory.available.source.empty()) {
    fmt::print("available        {} ({})\n", byte_size(memory.available.bytes),
               memory.available.source);
  }
}

}  // namespace

int run_info(const std::filesystem::path& scene_path, bool json) {
  const SceneDescription scene = read_scene(scene_path);
  const Model model = build_model_telling_warnings(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  Index pinned = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    pinned += model.pinned(i) ? 1 : 0;
  }
  if (json) {
    print_json(scene, model, timestep, pinned);
  } else {
    print_text(scene, model, timestep, pinned);
  }
  return kExitOk;
}

}  // namespace dinam
