// How soon dinam stops after SIGTERM, in each kind of long loop: the explicit steps of a large
// cloth, the implicit integrator's Newton iterations on a small and a large cloth, a relaxation
// settle, and a render drawing and encoding frames. Each run is started afresh, signalled after a
// delay spread over its first seconds, and timed from the signal to its exit (wait4).
//   cmake --build build --target bench_signal_latency && build/bench/bench_signal_latency
//   build/dinam
// Options after the program: --tries=N per case (default 8).
#include <fmt/format.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"

namespace {

struct Case {
  const char* name;
  const char* command;
  std::string scene;
};

std::string cloth(int cells, const char* integrator, const char* settle) {
  return fmt::format(R"(version: 1
name: latency
duration: 100
fps: 20
integrator: {}
{}
objects:
  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: {}, rows: {}}}, rotation: [90, 0, 0], translation: [0, 0, 1.5]}}
    material: {{preset: cotton}}
    pinned: {{box: {{min: [-0.01, -1, 1.49], max: [1.01, 1, 1.51]}}}}
)",
                     integrator, settle, cells, cells);
}

constexpr const char* kLongDrawing = R"(version: 1
name: latency
duration: 400
fps: 20
objects:
  - name: rope
    mesh: {polyline: {points: [[2, 0, 1.5], [2, 0, 1.0], [2.5, 0, 0.5]]}}
    material: {preset: nylon_rope}
    pinned: {box: {min: [1.9, -1, 1.49], max: [2.1, 1, 1.51]}}
)";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    fmt::print(stderr, "usage: {} path/to/dinam [--tries=N]\n", argv[0]);
    return 2;
  }
  const std::string dinam = argv[1];
  int tries = 8;
  for (int a = 2; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg.rfind("--tries=", 0) == 0) {
      tries = std::max(1, std::stoi(arg.substr(8)));
    }
  }
  const std::vector<Case> cases = {
      {"simulate, central differences, 300 × 300 cloth", "simulate",
       cloth(300, "central_difference", "")},
      {"simulate, implicit, 40 × 40 cloth", "simulate", cloth(40, "implicit", "")},
      {"simulate, implicit, 120 × 120 cloth", "simulate", cloth(120, "implicit", "")},
      {"simulate, relaxation settle, 60 × 60 cloth", "simulate",
       cloth(60, "central_difference",
             "settle: {method: relax, residual: 1e-12, duration: 10000}")},
      {"render, drawing and encoding 8000 frames", "render", kLongDrawing},
  };
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / fmt::format("dinam-signal-latency-{}", getpid());
  std::filesystem::create_directories(folder);
  fmt::print("| loop | tries | median, ms | worst, ms |\n|---|---|---|---|\n");
  for (const Case& c : cases) {
    const std::filesystem::path scene = folder / "scene.yaml";
    std::ofstream(scene) << c.scene;
    std::vector<double> latencies;
    for (int k = 0; k < tries; ++k) {
      const std::filesystem::path out = folder / "out";
      std::filesystem::remove_all(out);
      std::vector<std::string> arguments = {c.command, scene.string(), "-o", out.string(),
                                            "--force"};
      if (std::string(c.command) == "render") {
        arguments.insert(arguments.end(), {"--size", "160x90"});
      }
      const pid_t pid = dinam::bench::start_quietly(dinam, arguments);
      if (pid == 0) {
        fmt::print(stderr, "cannot start {}\n", dinam);
        return 1;
      }
      // From 1 s to 3 s after the start: past reading the scene, within the loop measured.
      std::this_thread::sleep_for(
          std::chrono::milliseconds(1000 + 2000 * k / std::max(1, tries - 1)));
      const auto signalled = std::chrono::steady_clock::now();
      kill(pid, SIGTERM);
      int status = 0;
      waitpid(pid, &status, 0);
      latencies.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - signalled)
              .count());
    }
    std::sort(latencies.begin(), latencies.end());
    fmt::print("| {} | {} | {:.0f} | {:.0f} |\n", c.name, tries, latencies[latencies.size() / 2],
               latencies.back());
    std::fflush(stdout);
  }
  std::filesystem::remove_all(folder);
  return 0;
}
