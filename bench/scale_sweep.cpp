// How every stage's cost grows with the model (issue 16): the log-log table of
// bench/notes/performance.md ("A million bars"). A plain program, one run prints it all:
//   cmake --build build --target bench_scale_sweep && build/bench/bench_scale_sweep
// Options: --sizes=1e4,1e5,1e6,3e6 (bars), --kinds=cloth,wire, --no-draw, --repeats=N.
// Two structures at each size (bench_scenes.hpp): a cloth (a grid with one diagonal per cell,
// bending springs) and a wire lattice (a square grid drawn as wires, bending and torsion
// springs). For each it prints the model build (scene to a model and its time step), the heap the
// model and a state hold per bar, a step's time and spring evaluations per second on 1 and 2
// threads, and one 1280 × 720 frame drawn at the default quality. Every time is a median.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "bench_scenes.hpp"
#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "median_time.hpp"
#include "model/model.hpp"
#include "model_measures.hpp"
#include "render/osmesa_renderer.hpp"
#include "rest_frame.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

// One row of the table.
struct Row {
  Index bars = 0;
  Index springs = 0;
  double build = 0.0;           // s, build_model
  double timestep = 0.0;        // s, choosing the step (the frequency bound)
  double bytes_per_bar = 0.0;   // model + state, heap in use
  double step[2] = {0.0, 0.0};  // s a step, 1 and 2 threads
  double draw = 0.0;            // s a 720p frame; 0 when not drawn
};

// A step's time on `threads` threads: the median over `repeats` runs of enough steps to take
// about a tenth of a second.
double step_seconds(const Model& model, double dt, int threads, int repeats) {
  set_thread_count(threads);
  State state = initial_state(model, dt);
  const int steps = std::max(2, static_cast<int>(1e7 / static_cast<double>(spring_count(model))));
  step(model, dt, {}, state);  // first touch of every array
  return median_seconds(repeats,
                        [&] {
                          for (int s = 0; s < steps; ++s) {
                            step(model, dt, {}, state);
                          }
                        }) /
         steps;
}

double draw_seconds(const SceneDescription& scene, const Model& model, int repeats) {
  set_thread_count(2);
  const RestFrame frame = rest_frame(scene, model);
  OsmesaRenderer renderer(render_settings(scene));
  Image image;
  renderer.render(frame.list, frame.positions, frame.camera, image);  // warm: uploads, shaders
  return median_seconds(repeats,
                        [&] { renderer.render(frame.list, frame.positions, frame.camera, image); });
}

Row measure(ScaleStructure structure, Index bars, bool draw, int repeats) {
  const SceneDescription scene = scale_scene(structure, bars);
  Row row;
  const double heap_before = heap_bytes_in_use();
  row.build = median_seconds(repeats, [&] { (void)build_model(scene); });
  const Model model = build_model(scene);
  double dt = 0.0;
  row.timestep = median_seconds(repeats, [&] {
    dt = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc).dt;
  });
  {
    const State state = initial_state(model, dt);
    row.bytes_per_bar = (heap_bytes_in_use() - heap_before) / model.bar_count();
  }
  row.bars = model.bar_count();
  row.springs = spring_count(model);
  for (const int threads : {1, 2}) {
    row.step[threads - 1] = step_seconds(model, dt, threads, repeats);
  }
  if (draw) {
    row.draw = draw_seconds(scene, model, repeats);
  }
  return row;
}

// The least-squares slope of log(cost) against log(bars): 1 is linear.
double slope(const std::vector<Row>& rows, double (*cost)(const Row&)) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const Row& row : rows) {
    const double x = std::log(static_cast<double>(row.bars));
    const double y = std::log(cost(row));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double n = static_cast<double>(rows.size());
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void print_table(const char* title, const std::vector<Row>& rows, bool draw) {
  fmt::print("\n{}\n\n", title);
  fmt::print(
      "| bars | springs | build | µs/bar | time step | bytes/bar | step, 1 thread | M evals/s | "
      "step, 2 threads | M evals/s | 720p draw |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const double evals = static_cast<double>(r.springs) * 1e-6;
    fmt::print(
        "| {} | {} | {:.3f} s | {:.2f} | {:.3f} s | {:.0f} | {:.3f} ms | {:.0f} | {:.3f} ms | "
        "{:.0f} | {} |\n",
        r.bars, r.springs, r.build, 1e6 * (r.build + r.timestep) / r.bars, r.timestep,
        r.bytes_per_bar, 1e3 * r.step[0], evals / r.step[0], 1e3 * r.step[1], evals / r.step[1],
        draw ? fmt::format("{:.0f} ms", 1e3 * r.draw) : "—");
  }
  if (rows.size() < 2) {
    return;
  }
  fmt::print(
      "\nslopes of log cost against log bars: build {:.2f}, time step {:.2f}, memory {:.2f}, "
      "step on 1 thread {:.2f}, on 2 threads {:.2f}",
      slope(rows, [](const Row& r) { return r.build; }),
      slope(rows, [](const Row& r) { return r.timestep; }),
      slope(rows, [](const Row& r) { return r.bytes_per_bar * r.bars; }),
      slope(rows, [](const Row& r) { return r.step[0]; }),
      slope(rows, [](const Row& r) { return r.step[1]; }));
  if (draw) {
    fmt::print(", draw {:.2f}", slope(rows, [](const Row& r) { return r.draw; }));
  }
  fmt::print("\n");
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');) {
    items.push_back(item);
  }
  return items;
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  std::vector<Index> sizes = {10'000, 100'000, 1'000'000, 3'000'000};
  std::vector<std::string> kinds = {"cloth", "wire"};
  bool draw = true;
  int repeats = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--sizes=", 0) == 0) {
      sizes.clear();
      for (const std::string& size : split(arg.substr(8))) {
        sizes.push_back(static_cast<Index>(std::stod(size)));
      }
    } else if (arg.rfind("--kinds=", 0) == 0) {
      kinds = split(arg.substr(8));
    } else if (arg == "--no-draw") {
      draw = false;
    } else if (arg.rfind("--repeats=", 0) == 0) {
      repeats = std::max(1, std::stoi(arg.substr(10)));
    } else {
      fmt::print(stderr,
                 "usage: bench_scale_sweep [--sizes=1e4,1e5,1e6,3e6] [--kinds=cloth,wire] "
                 "[--no-draw] [--repeats=3]\n");
      return 2;
    }
  }
  fmt::print("dinam scale sweep; threads {}, medians of {}\n", thread_count(), repeats);
  for (const std::string& kind : kinds) {
    const bool cloth = kind == "cloth";
    std::vector<Row> rows;
    for (const Index bars : sizes) {
      rows.push_back(measure(cloth ? ScaleStructure::kCloth : ScaleStructure::kWireLattice, bars,
                             draw, repeats));
      fmt::print(stderr, "{} {} bars done\n", kind, rows.back().bars);
    }
    print_table(cloth ? "cloth (grid with one diagonal a cell; axial and bending springs)"
                      : "wire lattice (square grid drawn as wires; axial, bending and torsion "
                        "springs)",
                rows, draw);
  }
  return 0;
}
