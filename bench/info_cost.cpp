// What `dinam info` costs as the model grows: its wall time and peak memory on a cloth grid
// (one diagonal per cell) of 10⁴ to 10⁶ bars, each a fresh process measured by wait4's rusage.
// info is the command users run first, so it must stay a small multiple of building the model:
//   cmake --build build --target bench_info_cost && build/bench/bench_info_cost build/dinam
// Options after the program: --sizes=1e4,1e5,1e6 (bars, about).
#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace {

struct Measure {
  double seconds = 0.0;
  double peak_mb = 0.0;
  int status = -1;
};

// Runs `dinam info SCENE`.
Measure run_info(const std::string& dinam, const std::filesystem::path& scene) {
  const auto start = std::chrono::steady_clock::now();
  Measure measure;
  const pid_t pid = dinam::bench::start_quietly(dinam, {"info", scene.string()});
  if (pid == 0) {
    return measure;
  }
  rusage usage{};
  wait4(pid, &measure.status, 0, &usage);
  measure.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  measure.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  return measure;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    fmt::print(stderr, "usage: {} path/to/dinam [--sizes=1e4,1e5,1e6]\n", argv[0]);
    return 2;
  }
  const std::string dinam = argv[1];
  std::vector<double> sizes = {1e4, 1e5, 1e6};
  for (int a = 2; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg.rfind("--sizes=", 0) == 0) {
      sizes.clear();
      std::stringstream list(arg.substr(8));
      for (std::string item; std::getline(list, item, ',');) {
        sizes.push_back(std::stod(item));
      }
    }
  }
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / fmt::format("dinam-info-cost-{}", getpid());
  std::filesystem::create_directories(folder);
  fmt::print("| bars | cells | info, s | peak memory, MB |\n|---|---|---|---|\n");
  for (const double bars : sizes) {
    // A grid of n × n cells with one diagonal has 3n² + 2n bars.
    const int cells = static_cast<int>(std::lround(std::sqrt(bars / 3.0)));
    const std::filesystem::path scene = folder / fmt::format("grid_{}.yaml", cells);
    std::ofstream(scene) << fmt::format(R"(version: 1
duration: 1
objects:
  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: {0}, rows: {0}, diagonals: one}},
            translation: [0, 0, 1]}}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001}}
    pinned: {{box: {{min: [-0.001, 0.999, 0], max: [1.001, 1.001, 2]}}}}
)",
                                        cells);
    const Measure m = run_info(dinam, scene);
    fmt::print("| {} | {} × {} | {:.2f} | {:.0f} |{}\n", 3 * cells * cells + 2 * cells, cells,
               cells, m.seconds, m.peak_mb,
               WIFEXITED(m.status) && WEXITSTATUS(m.status) == 0 ? "" : " (failed)");
    std::fflush(stdout);
  }
  std::filesystem::remove_all(folder);
  return 0;
}
