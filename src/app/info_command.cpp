// `dinam info`: the model summary, for a person or (--json) for a script such as the Slurm farm.
#include <fmt/format.h>

#include <fmt/ranges.h>
#include <memory>

#include <array>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "core/counted.hpp"
#include "core/thread_governor.hpp"
#include "dynamics/stability.hpp"
#include "estimate/integrator_choice.hpp"
#include "estimate/integrator_estimates.hpp"
#include "estimate/memory_estimate.hpp"
#include "estimate/run_estimate.hpp"
#include "model/model.hpp"
#include "model/step_limits.hpp"
#include "scene/material_presets.hpp"
#include "scene/scene_description.hpp"
#include "solver/implicit_damping.hpp"
#include "stepping/central_difference_stepper.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

// What `render` and `simulate` of this scene will hold at their peaks.
struct MemoryFigures {
  MemoryEstimate render;
  MemoryEstimate simulate;
  MemoryBudget available;
};

MemoryFigures memory_figures(const SceneDescription& scene, const Model& model) {
  const MotionBlurDesc& blur = scene.quality.motion_blur;
  return {estimate_memory(scene, model,
                          {scene.frame_count(), false, scene.image_width, scene.image_height,
                           blur.enabled() ? blur.samples : 0}),
          estimate_memory(scene, model, {2, false, 0, 0}), available_memory()};
}

// The box of the nodes at rest, m.
std::pair<Vec3, Vec3> bounding_box(const Model& model) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Vec3& x : model.node_initial_x) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return {lo, hi};
}

nlohmann::ordered_json json_vec3(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

// A step measured now this many times longer than the model's estimate says the machine is busy:
// the estimate is an idle machine's (step_cost.hpp), and a step timed on an idle one has come
// within a quarter of it.
constexpr double kBusyShare = 1.5;

// What `info` says about the run's time: the estimate from the model and what a step measures
// on this machine now.
struct RunFigures {
  RunEstimate estimate;
  MeasuredStep measured;
  ThreadChoice threads;
  IntegratorChoice choice;
};

// What each integrator would need, and the one recommended.
void print_integrator_choice(const IntegratorChoice& choice) {
  const ImplicitStepCost& step = choice.implicit.implicit;
  fmt::print(
      "integrators      central_difference: {} steps{}, about {}; xpbd: {} steps, about {}; "
      "implicit: {} steps ({}), about {} "
      "at {:g} Newton iterations, {:g} iterations of their solves "
      "and {:g} factorisations a step, as {} ({:.3g} ms a factorisation, of a factor of {:.3g} "
      "nonzeros for {:.0f} unknowns; docs/scene-format.md, \"integrator\")\n",
      choice.central_difference.steps,
      choice.central_difference_unscaled
          ? " (without the mass scaling that would lengthen them: no memory for its model)"
          : "",
      duration_text(choice.central_difference.seconds), choice.xpbd.steps,
      duration_text(choice.xpbd.seconds), choice.implicit.steps,
      choice.contact_envelope
          ? "at most: contact between objects moves no node more than half its smallest radius "
            "a step, and this counts a fall through the scene's height for the whole run"
          : "more where a step is split",
      duration_text(choice.implicit.seconds), step.counts.iterations, step.counts.solve_iterations,
      step.counts.factorizations, motion_text(step), 1e3 * step.factorization_seconds,
      step.factor.nonzeros, step.factor.unknowns);
  fmt::print("recommended      integrator: {} ({})\n", recommended_key(choice),
             recommendation_reason(choice));
}

void print_json(const SceneDescription& scene, const Model& model, const TimeStep& timestep,
                Index pinned, const RunFigures& run) {
  const MemoryFigures memory = memory_figures(scene, model);
  const StepLimits limits = find_step_limits(model);
  const std::pair<Vec3, Vec3> box = bounding_box(model);
  const EnergyBalanceGuide guide = energy_balance_guide(model, timestep);
  nlohmann::ordered_json objects = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < model.objects.size(); ++k) {
    const ModelObject& object = model.objects[k];
    const RawMesh& mesh = scene.objects[k].mesh;
    nlohmann::ordered_json material = {{"preset", scene.objects[k].material.preset},
                                       {"sheet", scene.objects[k].material.sheet.has_value()}};
    for (const MaterialValue& value : resolved_material_values(scene.objects[k].material)) {
      material[value.key] = value.value;
    }
    objects.push_back({{"name", object.name},
                       {"nodes", object.node_count},
                       {"bars", object.bar_count},
                       {"material", material},
                       {"mesh_materials", element_names(mesh, MeshNameKind::kMaterial)},
                       {"mesh_groups", element_names(mesh, MeshNameKind::kGroup)}});
  }
  nlohmann::ordered_json json = {
      {"scene", scene.source.string()},
      {"name", scene.name},
      {"objects", objects},
      {"nodes", model.node_count()},
      {"pinned_nodes", pinned},
      {"bars", model.bar_count()},
      {"bending_springs", model.bend_count()},
      {"torsion_springs", model.torsion_count()},
      {"total_mass_kg", model.total_mass()},
      {"bounding_box_m", {json_vec3(box.first), json_vec3(box.second)}},
      {"added_mass_kg", model.mass_scaling.added_mass},
      {"added_mass_fraction", model.mass_scaling.added_fraction()},
      {"mass_scaled_nodes", model.mass_scaling.nodes},
      {"shortest_bar_m", limits.shortest.empty() ? 0.0 : limits.shortest.front().length},
      {"median_bar_m", limits.median_length},
      {"stability_limit_s", timestep.critical},
      {"timestep_s", timestep.dt},
      {"steps_per_frame", timestep.steps_per_frame},
      {"omega_max_dt", guide.omega_dt},
      {"expected_energy_balance", guide.balance},
      {"timestep_for_0_1_percent_balance_s", guide.step_for_0_1},
      {"fps", scene.fps},
      {"frame_count", scene.frame_count()},
      {"duration_s", scene.duration},
      {"settle_s", model.settle.enabled ? model.settle.duration : 0.0},
      {"settle_residual", model.settle.enabled ? model.settle.residual : 0.0},
      {"settle_method", !model.settle.enabled                          ? "none"
                        : model.settle.method == SettleMethod::kNewton ? "newton"
                                                                       : "relax"},
      {"steps", steps_in_all(scene, model, timestep)},
      {"estimated_steps", run.estimate.steps},
      {"threads", run.estimate.step.threads},
      {"threads_chosen", run.threads.threads},
      {"threads_most", run.threads.most},
      {"threads_adapt", run.threads.adapts},
      {"threads_reason", run.threads.reason},
      {"seconds_per_step", run.estimate.step.seconds},
      {"estimated_run_s", run.estimate.seconds},
      {"measured_seconds_per_step", run.measured.seconds_per_step},
      {"measured_run_s", run.measured.seconds_per_step * static_cast<double>(run.estimate.steps)},
      {"central_difference_steps", run.choice.central_difference.steps},
      {"central_difference_estimated_run_s", run.choice.central_difference.seconds},
      {"xpbd_steps", run.choice.xpbd.steps},
      {"xpbd_estimated_run_s", run.choice.xpbd.seconds},
      {"implicit_steps", run.choice.implicit.steps},
      {"implicit_estimated_run_s", run.choice.implicit.seconds},
      {"recommended_integrator", recommended_key(run.choice)},
      {"memory_render_bytes", memory.render.peak()},
      {"memory_simulate_bytes", memory.simulate.peak()},
      {"memory_available_bytes", memory.available.bytes},
      {"output", scene.output.string()},
      {"movie", movie_format_name(scene.movie)},
  };
  if (const StepperKind& kind = stepper_kind(model); kind.numerical_damping != nullptr) {
    nlohmann::ordered_json modes = nlohmann::ordered_json::array();
    for (const ModeDamping& mode : kind.numerical_damping(timestep)) {
      modes.push_back({{"steps_per_period", mode.steps_per_period},
                       {"frequency_hz", mode.frequency},
                       {"backward_euler", mode.backward_euler},
                       {"bdf2", mode.bdf2}});
    }
    json["implicit_amplitude_kept_per_period"] = modes;
  }
  // A mesh file's material and group names are bytes in any encoding: what is not UTF-8 is shown
  // as U+FFFD rather than failing the whole summary.
  fmt::print("{}\n", json.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

// The shortest bars, what sets the step and any mass added to lengthen it.
void print_step_limits(const Model& model) {
  const StepLimits limits = find_step_limits(model);
  std::vector<std::string> shortest;
  for (const BarLength& bar : limits.shortest) {
    shortest.push_back(fmt::format("{:.3g}", bar.length));
  }
  fmt::print("shortest bars    {} m (median {:.3g} m)\n", fmt::join(shortest, ", "),
             limits.median_length);
  if (limits.fastest_node >= 0) {
    fmt::print("step set by      {}: {}\n", describe_node(model, limits.fastest_node),
               limits.contact_dominates
                   ? std::string("its contact penalty")
                   : fmt::format("its springs, shortest bar {:.3g} m", limits.shortest_at_fastest));
  }
  const MassScaling& scaling = model.mass_scaling;
  if (scaling.nodes > 0) {
    fmt::print(
        "mass scaling     +{:.3g} kg ({:.2f} % of {:.6g} kg) on {} nodes: the springs' stable "
        "step {:.2f}× longer{}\n",
        scaling.added_mass, 100.0 * scaling.added_fraction(), scaling.mass_before, scaling.nodes,
        scaling.step_gain,
        scaling.target_step > 0.0
            ? fmt::format(", aiming at {:.3g} s", scaling.target_step)
            : (scaling.capped ? std::string(", stopped at the added-mass limit") : std::string()));
  }
}

void print_text(const SceneDescription& scene, const Model& model, const TimeStep& timestep,
                Index pinned, const RunFigures& run) {
  const int frames = scene.frame_count();
  fmt::print("scene            {} ('{}')\n", scene.source.string(), scene.name);
  fmt::print("objects          {}\n", model.objects.size());
  for (std::size_t k = 0; k < model.objects.size(); ++k) {
    const ModelObject& object = model.objects[k];
    fmt::print("  {:<14} {} nodes, {} bars\n", object.name, object.node_count, object.bar_count);
    const MaterialDesc& material = scene.objects[k].material;
    std::vector<std::string> values;
    for (const MaterialValue& value : resolved_material_values(material)) {
      values.push_back(fmt::format("{} {:.4g}{}{}", value.key, value.value,
                                   *value.unit != 0 ? " " : "", value.unit));
    }
    fmt::print("  {:<14} {} {}: {}\n", "",
               material.preset.empty() ? "material" : "material " + material.preset,
               material.sheet ? "(a sheet)" : "(a wire or rope)", fmt::join(values, ", "));
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
  const auto [lo, hi] = bounding_box(model);
  fmt::print(
      "bounding box     {:.4g} × {:.4g} × {:.4g} m, from ({:.4g}, {:.4g}, {:.4g}) to "
      "({:.4g}, {:.4g}, {:.4g}) m\n",
      hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z(), lo.x(), lo.y(), lo.z(), hi.x(), hi.y(),
      hi.z());
  fmt::print("total mass       {:.6g} kg\n", model.total_mass());
  print_step_limits(model);
  fmt::print("stability limit  {:.6g} s ((2/ω)(√(1+ζ²) − ζ), ω and ζ bounded from above)\n",
             timestep.critical);
  fmt::print("time step        {:.6g} s ({})\n", timestep.dt,
             stepper_kind(model).timestep_note(model, timestep));
  fmt::print("steps per frame  {}\n", timestep.steps_per_frame);
  const long long steps_to_last_frame =
      static_cast<long long>(frames - 1) * timestep.steps_per_frame;
  fmt::print("frames           {} at {:g} fps, t = 0 … {:g} s\n", frames, scene.fps,
             (frames - 1) / scene.fps);
  fmt::print("steps            {} over the {:g} s duration ({} up to the last frame)\n",
             steps_to_last_frame + timestep.steps_per_frame, scene.duration, steps_to_last_frame);
  if (model.settle.enabled) {
    fmt::print(
        "settling         before t = 0 under gravity alone, {}, until the out-of-balance force "
        "on every node is below {:g} of its weight; relaxation at most {:g} s ({} steps)\n",
        model.settle.method == SettleMethod::kNewton
            ? "by Newton's method (relaxation where the way there decides the shape)"
            : "by relaxation",
        model.settle.residual, model.settle.duration,
        std::llround(model.settle.duration / timestep.dt));
  }
  fmt::print("steps in all     {}{}\n", steps_in_all(scene, model, timestep),
             model.settle.enabled ? " at most (settling stops once it has converged)" : "");
  const StepCost& cost = run.estimate.step;
  fmt::print("threads          {} ({}){}\n", run.threads.threads,
             run.threads.reason.empty() ? "set by the program" : run.threads.reason,
             cost.threads < run.threads.most
                 ? std::string("; this model's steps run on 1, too small to share")
                 : std::string());
  // On a busy machine a step takes longer than the model's counts say (they are an idle
  // machine's): the headline is then what the step measured now makes of the run.
  const IntegratorEstimate& integrator = integrator_estimate(stepper_kind(model));
  const bool busy = run.measured.steps > 0 &&
                    run.measured.seconds_per_step > kBusyShare * run.estimate.step.seconds;
  if (busy) {
    fmt::print(
        "run time         about {} to simulate now, at the {:.3g} ms a step measured on this "
        "machine as busy as it is; on an idle one, {}\n",
        duration_text(run.measured.seconds_per_step * static_cast<double>(run.estimate.steps)),
        1e3 * run.measured.seconds_per_step, integrator.run_time_note(model, run.estimate));
  } else {
    fmt::print("run time         {}\n", integrator.run_time_note(model, run.estimate));
  }
  if (integrator.step_can_be_timed) {
    if (run.measured.steps > 0) {
      fmt::print(
          "measured now     {:.3g} ms a step, {} steps timed on this machine as busy as it is "
          "now\n",
          1e3 * run.measured.seconds_per_step, run.measured.steps);
    } else {
      fmt::print("measured now     not measured: a run's memory is more than this machine has\n");
    }
  }
  print_integrator_choice(run.choice);
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

int run_info(const std::filesystem::path& scene_path, bool json, const ThreadChoice& threads,
             bool energy) {
  const SceneDescription scene = read_scene(scene_path);
  const Model model = build_model_telling_warnings(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  // info allocates beyond the model only within the memory budget, as render does: the probe's
  // state where a run's would fit, and a second model (central differences', for an implicit
  // scene) where there is room for it beside the first.
  const MemoryEstimate simulate = estimate_memory(scene, model, {2, false, 0, 0});
  const std::uint64_t available = available_memory().bytes;
  const bool room_for_a_run = simulate.peak() <= available;
  const bool room_for_another_model = simulate.peak() + 2 * simulate.model <= available;
  // A step of the implicit integrator is a Newton solve, which the probe (central differences'
  // step) does not measure.
  const RunFigures run{
      estimate_run(scene, model, timestep, thread_policy().most),
      !integrator_estimate(stepper_kind(model)).step_can_be_timed || !room_for_a_run
          ? MeasuredStep{}
          : measure_step_now(model, timestep),
      threads, compare_integrators(scene, model, thread_policy().most, room_for_another_model)};
  Index pinned = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    pinned += model.pinned(i) ? 1 : 0;
  }
  if (json) {
    print_json(scene, model, timestep, pinned, run);
  } else {
    print_text(scene, model, timestep, pinned, run);
    if (energy) {
      fmt::print("energy balance   {}\n", stepper_kind(model).energy_balance_note(model, timestep));
    }
  }
  return kExitOk;
}

Command add_info_command(CLI::App& app, std::optional<int>& threads) {
  struct Parsed {
    std::filesystem::path scene;
    bool json = false;
    bool energy = false;
  };
  auto parsed = std::make_shared<Parsed>();
  CLI::App* info_command =
      app.add_subcommand("info",
                         "Print what a scene holds and what a run of it will take, without "
                         "running it: nodes, bars, springs, mass, the time step and what sets "
                         "it, the run's time and memory, and the integrator recommended");
  info_command->add_option("scene", parsed->scene, "Scene file (YAML)")->required();
  info_command->add_flag("--json", parsed->json, "Print one JSON object, for scripts");
  info_command->add_flag("--energy", parsed->energy,
                         "Also say what energy balance the time step gives (energy.csv's "
                         "total_J) and what step gives 0.1 %");
  add_threads_option(*info_command, threads);

  return {info_command, [parsed](const ThreadChoice& thread_choice) {
            return run_info(parsed->scene, parsed->json, thread_choice, parsed->energy);
          }};
}

}  // namespace dinam
