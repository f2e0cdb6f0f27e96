// The cost of every force kind per step, on the large flag, on 1 and 2 threads: the table of
// bench/notes/performance.md ("Every force kind against the springs"). A plain program, one run
// prints it all:
//   cmake --build build --target bench_force_costs && build/bench/bench_force_costs
// With the path of a dinam program (build/bench/bench_force_costs build/dinam) it also times
// whole renders of windy cloths (report_whole_renders); --only=TEXT measures only the kinds whose
// name holds TEXT. Each figure is the median of 7 batches of
// calls (each batch at least 20 ms), in nanoseconds per item (the item each kind loops over: a
// spring, a node, a face or a bar in the wind), and as a ratio to the axial springs' cost per bar
// on the same thread count.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <cstdlib>
#include <regex>

#include "core/thread_team.hpp"
#include "dynamics/axial_spring.hpp"
#include "dynamics/bending_spring.hpp"
#include "dynamics/clamp_spring.hpp"
#include "dynamics/contact/ground_contact.hpp"
#include "dynamics/field_forces.hpp"
#include "dynamics/global_damping.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/torsion_spring.hpp"
#include "dynamics/wind.hpp"
#include "dynamics/work_split.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

using Clock = std::chrono::steady_clock;

// The large flag of bench_scenes.hpp (180 × 180 cells, one diagonal, torsion on), with what the
// kinds below need switched on: `extra` adds top-level keys, `material` material keys.
SceneDescription flag_scene(const std::string& extra, const std::string& material = "") {
  return read_scene_text(fmt::format(R"(version: 1
duration: 1
damping: {{global: 0.1}}
forces:
  - {{acceleration: [8, 0, 0], object: cloth, profile: {{type: step, start: 0}}}}
{}
objects:
  - name: cloth
    mesh:
      grid: {{width: 3.6, height: 3.6, columns: 180, rows: 180, diagonals: one}}
      rotation: [90, 0, 0]
      translation: [0, 0, 1.0]
    material: {{density: 1200, youngs_modulus: 5.0e6, radius: 0.001{}}}
    pinned: {{box: {{min: [-0.01, -0.01, 0], max: [0.01, 0.01, 5]}}}}
    damping: {{axial_ratio: 0.05}}
    initial_velocity: [0, 0.8, 0]
)",
                                     extra, material),
                         std::filesystem::temp_directory_path() / "force_costs.yaml");
}

// A wire lattice of the same 181 × 181 nodes and bars, without faces: every bar feels the wind as
// a cylinder in cross flow.
SceneDescription lattice_scene(const std::string& wind) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path();
  constexpr int kCells = 180;
  std::string obj;
  for (int row = 0; row <= kCells; ++row) {
    for (int column = 0; column <= kCells; ++column) {
      obj += fmt::format("v {} 0 {}\n", 0.02 * column, 1.0 + 0.02 * row);
    }
  }
  auto id = [](int row, int column) { return row * (kCells + 1) + column + 1; };
  for (int row = 0; row <= kCells; ++row) {
    for (int column = 0; column <= kCells; ++column) {
      if (column < kCells) {
        obj += fmt::format("l {} {}\n", id(row, column), id(row, column + 1));
      }
      if (row < kCells) {
        obj += fmt::format("l {} {}\n", id(row, column), id(row + 1, column));
      }
      if (row < kCells && column < kCells) {
        obj += fmt::format("l {} {}\n", id(row, column), id(row + 1, column + 1));
      }
    }
  }
  std::ofstream(folder / "force_costs_lattice.obj") << obj;
  return read_scene_text(fmt::format(R"(version: 1
duration: 1
{}
objects:
  - name: lattice
    mesh: {{file: force_costs_lattice.obj}}
    material: {{density: 1200, youngs_modulus: 5.0e6, radius: 0.001}}
    pinned: {{box: {{min: [-0.01, -1, 0], max: [0.01, 1, 5]}}}}
    initial_velocity: [0, 0.8, 0]
)",
                                     wind),
                         folder / "force_costs_lattice.yaml");
}

constexpr const char* kSteadyWind = "wind: {velocity: [6, 0, 0], gust: {amplitude: 2.5}}";
constexpr const char* kTurbulentWind =
    "wind: {velocity: [6, 0, 0], gust: {amplitude: 2.5}, turbulence: {amplitude: 1.2, scale: 0.8}}";

// A model with its state `warm_steps` steps into its motion, so that every spring is loaded.
struct Loaded {
  Model model;
  State state;
  double dt;
  Loaded(const SceneDescription& scene, int warm_steps) : model(build_model(scene)) {
    dt = kAutoTimestepSafety * critical_timestep(model);
    state = initial_state(model, dt);
    for (int s = 0; s < warm_steps; ++s) {
      step(model, dt, {}, state);
    }
  }
};

// Median seconds per call of `call` over 7 batches of at least 20 ms each.
double seconds_per_call(const std::function<void()>& call) {
  call();  // warm: first touch of the arrays, the threads woken
  int calls = 1;
  for (;;) {
    const auto start = Clock::now();
    for (int c = 0; c < calls; ++c) {
      call();
    }
    if (std::chrono::duration<double>(Clock::now() - start).count() >= 0.02) {
      break;
    }
    calls *= 2;
  }
  std::vector<double> batches;
  for (int b = 0; b < 7; ++b) {
    const auto start = Clock::now();
    for (int c = 0; c < calls; ++c) {
      call();
    }
    batches.push_back(std::chrono::duration<double>(Clock::now() - start).count() / calls);
  }
  std::sort(batches.begin(), batches.end());
  return batches[3];
}

struct Row {
  std::string kind;
  std::string item;
  Index items;
  double ns_per_item[2];  // 1 and 2 threads
};

// The cost of one kind's add function over the model, history kept (as a step does), run as a
// step runs it: one job of the thread team, each member its share (dynamics/work_split.hpp).
template <class Add>
double add_seconds(Loaded& loaded, const Add& add) {
  State state = loaded.state;  // a copy: plastic sets and anchors move on in it, not in `loaded`
  const WorkSplit* split = share_work(loaded.model, state);
  return seconds_per_call([&] {
    thread_team().run([&](const TeamMember& member) {
      ForceContext context{loaded.model, state,           state.force, true,
                           nullptr,      {member, split}, state.time};
      add(context);
      // The plastic sets of shared springs that a step would commit after its meeting: dropped.
      if (split != nullptr) {
        state.plastic_set_updates[static_cast<std::size_t>(member.index())].clear();
      }
    });
  });
}

// The wind as a step adds it: the drag on the items, then each node's share.
void add_all_wind_forces(ForceContext& context) {
  compute_wind_drag(context);
  add_wind_forces(context);
}

// Whole renders, as a user runs them: `dinam render` of the shipped windy flag, and of that
// flag's cloth refined to 120 × 120 cells (14 641 nodes, 43 440 bars, 130 797 springs) for
// 0.13 s, with the forces added one by one. Median of 3 wall times, s, on the threads the
// program chooses.
void report_whole_renders(const std::string& program) {
  const std::filesystem::path source = DINAM_SOURCE_DIR;
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "force_costs";
  std::filesystem::create_directories(folder);
  std::string windy;
  {
    std::ifstream in(source / "scenes/windy_flag.yaml");
    windy.assign(std::istreambuf_iterator<char>(in), {});
  }
  // The texture found from the temporary folder; the cloth refined, then the forces removed.
  windy = std::regex_replace(windy, std::regex("\\.\\./assets/"), (source / "assets/").string());
  // 0.13 s of it: about 2 700 steps of 48 µs, three frames.
  std::string fine =
      std::regex_replace(windy, std::regex("columns: 24, rows: 16"), "columns: 120, rows: 120");
  fine = std::regex_replace(fine, std::regex("duration: 6.0"), "duration: 0.13");
  const std::string no_wind = std::regex_replace(fine, std::regex("wind:\\n(  .*\\n)+"), "");
  const std::string plastic = std::regex_replace(no_wind, std::regex("radius: 0.001\\}"),
                                                 "radius: 0.001, yield_stress: 5.0e5}");
  const std::string steady = std::regex_replace(
      plastic, std::regex("objects:\\n  - name: pole"),
      "wind: {velocity: [6, 0, 0], gust: {amplitude: 2.5, period: 2.3}, objects: [cloth]}\n"
      "objects:\n  - name: pole");
  const std::string turbulent =
      std::regex_replace(steady, std::regex("objects: \\[cloth\\]\\}"),
                         "turbulence: {amplitude: 1.2, scale: 0.8, seed: 7}, objects: [cloth]}");
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"the shipped windy flag (24 × 16 cells)", windy},
      {"120 × 120 cloth: springs, gravity, ground", no_wind},
      {"  + plasticity (yield_stress)", plastic},
      {"  + steady wind with gusts", steady},
      {"  + turbulence", turbulent}};
  for (const auto& [name, text] : runs) {
    const std::filesystem::path scene = folder / "scene.yaml";
    std::ofstream(scene) << text;
    const std::string command = fmt::format("'{}' render '{}' -o '{}' -q", program, scene.string(),
                                            (folder / "out").string());
    std::vector<double> times;
    for (int r = 0; r < 3; ++r) {
      const auto start = Clock::now();
      if (std::system(command.c_str()) != 0) {
        fmt::print(stderr, "failed: {}\n", command);
        std::exit(1);
      }
      times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    fmt::print("| {} | {:.2f} s |\n", name, times[1]);
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  // --only=TEXT measures only the kinds whose name holds TEXT (for a profiler); a further
  // argument is the dinam program for the whole renders.
  std::string only;
  std::string program;
  for (int a = 1; a < argc; ++a) {
    const std::string argument = argv[a];
    if (argument.rfind("--only=", 0) == 0) {
      only = argument.substr(7);
    } else {
      program = argument;
    }
  }
  fmt::print("dinam force-cost benchmark: the large flag, threads {}\n\n", thread_count());
  Loaded elastic(flag_scene(kSteadyWind), 50);
  Loaded yielding(flag_scene("", ", yield_stress: 1.0e5"), 50);
  Loaded turbulent(flag_scene(kTurbulentWind), 0);
  // The ground through the middle of the hanging flag: half of its nodes touch and rub. (A scene
  // cannot start with nodes in the ground, so the plane is raised after the build.)
  Loaded grounded(flag_scene(""), 0);
  grounded.model.ground.point = Vec3(0, 0, 2.8);
  Loaded lattice(lattice_scene(kSteadyWind), 0);
  Loaded turbulent_lattice(lattice_scene(kTurbulentWind), 0);
  for (Loaded* copy : {&turbulent, &grounded}) {  // the loaded shape of the flag
    copy->state.x = elastic.state.x;
    copy->state.velocity = elastic.state.velocity;
    copy->state.time = elastic.state.time;
  }
  const Model& flag = elastic.model;
  Index touching = 0;
  for (const Vec3& x : grounded.state.x) {
    touching += x.z() < 2.8 ? 1 : 0;
  }

  std::vector<Row> rows;
  auto measure = [&](const std::string& kind, const std::string& item, Index items,
                     const std::function<double()>& seconds) {
    if (kind.find(only) == std::string::npos && kind != "axial springs") {
      return;  // (the axial springs always: every ratio is to them)
    }
    Row row{kind, item, items, {0.0, 0.0}};
    for (const int threads : {1, 2}) {
      set_thread_count(threads);
      row.ns_per_item[threads - 1] = 1e9 * seconds() / static_cast<double>(items);
    }
    rows.push_back(row);
    fmt::print(stderr, "{:<40} {:8.2f} {:8.2f} ns per {}\n", kind, row.ns_per_item[0],
               row.ns_per_item[1], item);
  };
  auto add = [](Loaded& loaded, void (*function)(ForceContext&)) {
    return [&loaded, function] { return add_seconds(loaded, function); };
  };
  const Index bars = flag.bar_count();
  const Index nodes = flag.node_count();
  measure("axial springs", "bar", bars, add(elastic, add_axial_spring_forces));
  measure("axial springs, yielding", "bar", bars, add(yielding, add_axial_spring_forces));
  measure("bending springs", "spring", flag.bend_count(), add(elastic, add_bending_spring_forces));
  measure("bending springs, yielding", "spring", flag.bend_count(),
          add(yielding, add_bending_spring_forces));
  measure("torsion springs", "spring", flag.torsion_count(),
          add(elastic, add_torsion_spring_forces));
  measure("torsion springs, yielding", "spring", flag.torsion_count(),
          add(yielding, add_torsion_spring_forces));
  measure("axial dampers", "bar", bars, add(elastic, add_axial_damper_forces));
  measure("global damping", "node", nodes, add(elastic, [](ForceContext& context) {
            add_global_damping_forces(context, context.model.global_damping);
          }));
  measure("gravity", "node", nodes, add(elastic, add_gravity_forces));
  measure("fields (one on every node)", "node", nodes, add(elastic, add_field_forces));
  measure(fmt::format("ground contact with friction ({} nodes touch)", touching), "node", nodes,
          [&] {
            return add_seconds(grounded,
                               [](ForceContext& context) { add_ground_contact_forces(context); });
          });
  measure("wind on faces, steady with gusts", "face", static_cast<Index>(flag.wind.faces.size()),
          add(elastic, add_all_wind_forces));
  measure("wind on faces, turbulent", "face", static_cast<Index>(turbulent.model.wind.faces.size()),
          add(turbulent, add_all_wind_forces));
  measure("wind on bars, steady with gusts", "bar",
          static_cast<Index>(lattice.model.wind.bars.size()), add(lattice, add_all_wind_forces));
  measure("wind on bars, turbulent", "bar",
          static_cast<Index>(turbulent_lattice.model.wind.bars.size()),
          add(turbulent_lattice, add_all_wind_forces));
  // The integrator alone: a step with every force switched off clears the forces, updates the
  // velocities and positions and checks that they are finite.
  measure("integrator and finite check", "node", nodes, [&] {
    State state = elastic.state;
    ForceSwitches none;
    none = {false, false, false, false, false, false, false, false, false, false};
    return seconds_per_call([&] { step(elastic.model, elastic.dt, none, state); });
  });

  fmt::print(
      "{} nodes, {} bars, {} bending and {} torsion springs, {} faces; {} bars in the "
      "lattice\n\n",
      nodes, bars, flag.bend_count(), flag.torsion_count(), flag.wind.faces.size(),
      lattice.model.wind.bars.size());
  fmt::print(
      "| force kind | item | ns per item, 1 thread | × axial | ns per item, 2 threads | "
      "× axial |\n|---|---|---|---|---|---|\n");
  const Row& axial = rows.front();
  for (const Row& row : rows) {
    fmt::print("| {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n", row.kind, row.item,
               row.ns_per_item[0], row.ns_per_item[0] / axial.ns_per_item[0], row.ns_per_item[1],
               row.ns_per_item[1] / axial.ns_per_item[1]);
  }
  if (!program.empty()) {  // the whole renders, with the dinam program given
    set_thread_count(2);
    fmt::print("\n| `dinam render`, 2 threads | wall time |\n|---|---|\n");
    std::fflush(stdout);
    report_whole_renders(program);
  }
  return 0;
}
