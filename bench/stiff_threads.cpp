// The solvers for stiff threads side by side (issue 68; bench/notes/stiff-threads.md), on one
// thread, each scene's motion against central differences' at their own step:
//   cmake --build build --target bench_stiff_threads && build/bench/bench_stiff_threads
//       [--budget S] [--scene windy_flag|drape|cable|flag]
// The families: central differences (the reference); the bars as constraints (`integrator:
// xpbd`, XPBD projection with the other springs explicit); backward Euler and BDF2 by Newton's
// method in a trust region (`implicit`, `implicit_bdf2`); BDF2 by quasi-Newton about projective
// dynamics' constant matrix (Liu et al. 2017, solver/quasi_newton.hpp). Each runs frame by frame
// until its scene's window ends or it has spent --budget seconds (default 60), and is measured on
// the frames it reached: the windy flag's and the paper's flag's mean cloth position over the
// window against central differences' (the flutter is chaotic, its mean is what compares), the
// drape's rest shape at the end (every node's distance), the cable's tip over its swing (the
// largest distance at a frame).
#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/thread_team.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "solver/implicit_integrator.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// An icosphere of radius r, subdivided twice (162 points), as an OBJ file: the drape's support.
std::filesystem::path write_sphere(double radius) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (Vec3& p : v) {
    p.normalize();
  }
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto [at, added] = middle.try_emplace(key, static_cast<int>(v.size()));
      if (added) {
        v.push_back((0.5 * (v[a] + v[b])).normalized());
      }
      return at->second;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : f) {
      const int ab = mid(a, b);
      const int bc = mid(b, c);
      const int ca = mid(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    f = finer;
  }
  const auto path = std::filesystem::temp_directory_path() / "bench_stiff_threads_sphere.obj";
  std::ofstream out(path);
  for (const Vec3& p : v) {
    out << fmt::format("v {} {} {}\n", radius * p.x(), radius * p.y(), radius * p.z());
  }
  for (const auto& [a, b, c] : f) {
    out << fmt::format("f {} {} {}\n", a + 1, b + 1, c + 1);
  }
  return path;
}

enum class Measure { kMeanPosition, kRestShape, kTip };

struct BenchScene {
  std::string name;
  SceneDescription scene;
  std::string object;  // whose nodes are measured
  double window;       // s of motion
  int from_frame;      // the mean's first frame (1-based), kMeanPosition
  Measure measure;
};

std::vector<BenchScene> bench_scenes() {
  const std::filesystem::path source = DINAM_SOURCE_DIR;
  std::vector<BenchScene> scenes;
  scenes.push_back({"windy_flag", read_scene(source / "scenes/windy_flag.yaml"), "cloth", 6.0, 20,
                    Measure::kMeanPosition});
  // A 1.4 m denim square (40 × 40 cells) dropped over a sphere of 0.3 m: where it comes to rest.
  const std::filesystem::path sphere = write_sphere(0.3);
  scenes.push_back({"drape",
                    read_scene_text(fmt::format(R"(version: 1
duration: 3
fps: 24
contact: {{objects: true}}
damping: {{global: 0.5}}
objects:
  - name: sphere
    mesh: {{file: "{}", translation: [0, 0, 0.6]}}
    material: {{density: 7850, youngs_modulus: 2.0e11, radius: 0.005}}
    pinned: {{all: true}}
  - name: cloth
    mesh:
      grid: {{width: 1.4, height: 1.4, columns: 40, rows: 40, diagonals: one}}
      translation: [-0.7, -0.7, 1.0]
    material: {{preset: denim}}
)",
                                                sphere.string()),
                                    std::filesystem::temp_directory_path() / "drape.yaml"),
                    "cloth", 3.0, 1, Measure::kRestShape});
  // A 2 m steel cable (the preset: 6 mm wire rope) let swing down from level, pinned at one end.
  scenes.push_back({"cable",
                    read_scene_text(R"(version: 1
duration: 3
fps: 24
ground: {contact: false, visible: false}
objects:
  - name: cable
    mesh: {polyline: {points: [[0, 0, 2.2], [2, 0, 2.2]], segments: 100}}
    material: {preset: steel_cable}
    pinned: {indices: [0]}
)",
                                    std::filesystem::temp_directory_path() / "cable.yaml"),
                    "cable", 3.0, 1, Measure::kTip});
  scenes.push_back(
      {"flag", read_scene(source / "scenes/flag.yaml"), "flag", 6.0, 20, Measure::kMeanPosition});
  return scenes;
}

struct Method {
  std::string name;
  IntegratorKind integrator;
  ImplicitScheme scheme;
  bool quasi_newton;
};

// One run: the measured object's nodes at each frame reached, and the seconds it took.
struct Run {
  std::vector<std::vector<Vec3>> frames;  // frame 1 (t = 0) onwards
  double seconds = 0.0;
  double step = 0.0;
  bool finished = false;
};

Run run_method(const BenchScene& bench, const Method& method, double budget) {
  SceneDescription scene = bench.scene;
  if (method.integrator != IntegratorKind::kCentralDifference) {
    scene.timestep.reset();  // each at its own automatic step; central differences at the scene's
  }
  scene.integrator = method.integrator;
  scene.implicit_scheme = method.scheme;
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const ModelObject* object = nullptr;
  for (const ModelObject& o : model.objects) {
    if (o.name == bench.object) {
      object = &o;
    }
  }
  Run run;
  run.step = timestep.dt;
  const int frames = static_cast<int>(std::lround(bench.window * scene.fps));
  auto keep = [&](const State& state) {
    run.frames.emplace_back(state.x.begin() + object->first_node,
                            state.x.begin() + object->first_node + object->node_count);
  };
  const auto start = std::chrono::steady_clock::now();
  std::function<void(State&)> advance_frame;
  State state;
  std::unique_ptr<Stepper> stepper;
  std::unique_ptr<ImplicitIntegrator> quasi;
  if (method.quasi_newton) {
    quasi = std::make_unique<ImplicitIntegrator>(
        model,
        ImplicitOptions{.longest_step = timestep.dt, .minimiser = ImplicitMinimiser::kQuasiNewton});
    state = initial_state(quasi->model(), timestep.dt);
    advance_frame = [&](State& s) { quasi->advance(s, timestep.dt, timestep.steps_per_frame); };
  } else {
    stepper = stepper_kind(model).make_stepper(model, timestep);
    state = stepper->start(false);
    advance_frame = [&](State& s) { stepper->advance(s, timestep.steps_per_frame); };
  }
  keep(state);
  try {
    for (int frame = 1; frame < frames && seconds_since(start) < budget; ++frame) {
      advance_frame(state);
      keep(state);
    }
    run.finished = static_cast<int>(run.frames.size()) == frames;
  } catch (const std::exception& error) {
    fmt::print("  ({} stopped: {})\n", method.name, error.what());
  }
  run.seconds = seconds_since(start);
  return run;
}

Vec3 mean_position(const Run& run, int from_frame, std::size_t to_frame) {
  Vec3 sum = Vec3::Zero();
  std::size_t count = 0;
  for (std::size_t f = static_cast<std::size_t>(from_frame - 1); f < to_frame; ++f) {
    for (const Vec3& p : run.frames[f]) {
      sum += p;
      ++count;
    }
  }
  return count > 0 ? Vec3(sum / static_cast<double>(count)) : Vec3::Zero();
}

// The measure of `run` against the reference, m, over the frames both reached.
std::string compare(const BenchScene& bench, const Run& run, const Run& reference) {
  const std::size_t frames = std::min(run.frames.size(), reference.frames.size());
  switch (bench.measure) {
    case Measure::kMeanPosition: {
      if (frames < static_cast<std::size_t>(bench.from_frame)) {
        return "too few frames";
      }
      const double apart = (mean_position(run, bench.from_frame, frames) -
                            mean_position(reference, bench.from_frame, frames))
                               .norm();
      return fmt::format("mean {:.1f} cm apart (frames {}–{})", 100.0 * apart, bench.from_frame,
                         frames);
    }
    case Measure::kRestShape: {
      if (!run.finished) {
        return "did not reach rest";
      }
      double largest = 0.0;
      double sum = 0.0;
      for (std::size_t i = 0; i < run.frames.back().size(); ++i) {
        const double d = (run.frames.back()[i] - reference.frames.back()[i]).norm();
        largest = std::max(largest, d);
        sum += d;
      }
      return fmt::format("rest shape: nodes {:.1f} cm apart on average, {:.1f} at most",
                         100.0 * sum / static_cast<double>(run.frames.back().size()),
                         100.0 * largest);
    }
    case Measure::kTip: {
      double largest = 0.0;
      for (std::size_t f = 0; f < frames; ++f) {
        largest = std::max(largest, (run.frames[f].back() - reference.frames[f].back()).norm());
      }
      return fmt::format("tip within {:.1f} cm over {} frames", 100.0 * largest, frames);
    }
  }
  return "";
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  double budget = 60.0;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--budget") == 0 && i + 1 < argc) {
      budget = std::stod(argv[++i]);
    } else if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc) {
      only = argv[++i];
    }
  }
  set_thread_count(1);
  const std::vector<Method> methods = {
      {"central_difference", IntegratorKind::kCentralDifference, ImplicitScheme::kBackwardEuler,
       false},
      {"xpbd", IntegratorKind::kXpbd, ImplicitScheme::kBackwardEuler, false},
      {"implicit", IntegratorKind::kImplicit, ImplicitScheme::kBackwardEuler, false},
      {"implicit_bdf2", IntegratorKind::kImplicit, ImplicitScheme::kBdf2, false},
      {"bdf2 quasi-Newton", IntegratorKind::kImplicit, ImplicitScheme::kBdf2, true},
  };
  fmt::print(
      "| scene | method | step | motion | time | × central differences | against central "
      "differences |\n|---|---|---|---|---|---|---|\n");
  for (const BenchScene& bench : bench_scenes()) {
    if (!only.empty() && bench.name != only) {
      continue;
    }
    Run reference;
    for (const Method& method : methods) {
      const Run run = run_method(bench, method, budget);
      const double motion = static_cast<double>(run.frames.size() - 1) / bench.scene.fps;
      const double rate = run.seconds / std::max(motion, 1e-9);  // s a second of motion
      if (&method == &methods.front()) {
        reference = run;
      }
      const double reference_rate =
          reference.seconds /
          std::max(static_cast<double>(reference.frames.size() - 1) / bench.scene.fps, 1e-9);
      fmt::print("| {} | {} | {:.3g} s | {:.2f} s{} | {:.2f} s | {:.3f} | {} |\n", bench.name,
                 method.name, run.step, motion, run.finished ? "" : " (stopped)", run.seconds,
                 rate / reference_rate,
                 &method == &methods.front() ? "reference" : compare(bench, run, reference));
      std::fflush(stdout);
    }
  }
  return 0;
}
