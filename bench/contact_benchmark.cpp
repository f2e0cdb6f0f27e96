// The cost of contact (bench/notes/performance.md), as whole steps with and without it, on 1 and 2
// threads:
//  - the large flag (about 100 000 bars, torsion on) falling from its corner, without contact,
//    with self-contact (contact radius 5 mm, a quarter of its cells: the cost of watching for
//    contact where little touches), and with contact against a pinned pole of 40 bars beside it;
//  - a cloth lying on itself: two 127 × 127 sheets of one object (also about 100 000 bars), one
//    on the floor and one let go just out of reach above it (6 mm, contact radii 3 mm, so every
//    node of each is within reach of the other's nodes, bars and triangles), which lands and
//    ripples on it with patches touching (the worst case of self-contact: about 7 candidate
//    pairs per bar), and the same sheets without contact.
//   cmake --build build --target bench_contact && build/bench/bench_contact
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bench_scenes.hpp"
#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

enum Case { kNoContact, kSelfContact, kObstacle, kSheetsApart, kSheetsPressed };

// Two square sheets of `cells` × `cells` cells, one on the floor and one 6.2 mm above it, as one
// OBJ mesh in `path`.
void write_two_sheets(const std::filesystem::path& path, int cells) {
  std::ofstream obj(path);
  const double cell = 1.0 / cells;
  for (int sheet = 0; sheet < 2; ++sheet) {
    for (int j = 0; j <= cells; ++j) {
      for (int i = 0; i <= cells; ++i) {
        obj << "v " << cell * i << " " << cell * j << " " << 0.006 * sheet << "\n";
      }
    }
  }
  const int per_sheet = (cells + 1) * (cells + 1);
  for (int sheet = 0; sheet < 2; ++sheet) {
    for (int j = 0; j < cells; ++j) {
      for (int i = 0; i < cells; ++i) {
        const int a = sheet * per_sheet + j * (cells + 1) + i + 1;  // OBJ counts from 1
        obj << "f " << a << " " << a + 1 << " " << a + cells + 2 << "\nf " << a << " "
            << a + cells + 2 << " " << a + cells + 1 << "\n";
      }
    }
  }
}

SceneDescription sheets_scene(bool contact) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path();
  write_two_sheets(folder / "dinam_bench_sheets.obj", 127);
  return read_scene_text(std::string("version: 1\nduration: 1\ngravity: [0, 0, -9.81]\n") +
                             (contact ? "contact: {self: true, damping_ratio: 1}\n" : "") +
                             R"(objects:
  - name: sheets
    mesh: {file: dinam_bench_sheets.obj}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
    contact: {radius: 0.003}
)",
                         folder / "dinam_bench_sheets.yaml");
}

SceneDescription contact_scene(Case which) {
  if (which == kSheetsApart || which == kSheetsPressed) {
    return sheets_scene(which == kSheetsPressed);
  }
  SceneDescription scene = large_flag_scene(true, which == kSelfContact ? "{self: true}"
                                                  : which == kObstacle  ? "{objects: true}"
                                                                        : "");
  if (which == kSelfContact) {
    scene.objects[0].contact.radius = 0.005;
  }
  if (which == kObstacle) {
    // A pole the falling cloth sweeps against, as a flag's pole.
    SceneDescription pole = read_scene_text(R"(version: 1
duration: 1
objects:
  - name: pole
    mesh: {polyline: {points: [[1.0, -0.05, -1.0], [1.0, -0.05, 1.2]], segments: 40}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.02}
    pinned: {all: true}
)",
                                            "pole.yaml");
    scene.objects.push_back(std::move(pole.objects[0]));
    scene.objects[0].contact.radius = 0.005;
  }
  return scene;
}

// range(0): the case; range(1): threads. Every iteration is one step of the falling flag, after
// 200 steps so that it is moving.
void flag_step_with_contact(benchmark::State& bench) {
  const auto which = static_cast<Case>(bench.range(0));
  const Model model = build_model(contact_scene(which));
  set_thread_count(static_cast<int>(bench.range(1)));
  const double dt = kAutoTimestepSafety * critical_timestep(model);
  State state = initial_state(model, dt);
  for (int s = 0; s < 200; ++s) {
    step(model, dt, {}, state);
  }
  for (auto _ : bench) {
    step(model, dt, {}, state);
    benchmark::ClobberMemory();
  }
  bench.counters["bars"] = static_cast<double>(model.bar_count());
  bench.counters["time_ms"] = 1e3 * state.time;
  bench.counters["touching"] = static_cast<double>(state.object_contact.previous.size());
  bench.counters["candidates"] = static_cast<double>(state.object_contact.candidates.size());
  bench.counters["searches_per_step"] =
      static_cast<double>(state.object_contact.searches) / static_cast<double>(state.step);
}
BENCHMARK(flag_step_with_contact)
    ->ArgsProduct({{kNoContact, kSelfContact, kObstacle, kSheetsApart, kSheetsPressed}, {1, 2}})
    ->ArgNames({"case", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace dinam

BENCHMARK_MAIN();
