// How the step scales with threads, on an idle machine and on one that other work shares
// (issue 29): the table of bench/notes/performance.md ("Threads on a shared machine"). A plain
// program, one run prints it all:
//   cmake --build build --target bench_threads && build/bench/bench_threads
// Options: --models=wuson,cloth,lattice (a subset), --repeats=N (batches a figure, default 5),
// --busy=N (busy processes for the shared half, default one per core).
//
// For each model it times a step on 1 and 2 threads with the machine as it is, then again while
// one busy process per core (`yes > /dev/null`, started and stopped by this program) competes
// for every core, as on a laptop, a CI runner or a shared farm node. Each figure is the median of
// `repeats` batches of steps of about a quarter of a second each. The targets it prints beside
// the figures: 2 threads at least 1.8× faster than 1 when idle; when busy, 2 threads never slower
// than 1 and at most 2.5× their idle time.
#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_scenes.hpp"
#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/work_split.hpp"
#include "median_time.hpp"
#include "model/model.hpp"
#include "model_measures.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

struct BenchModel {
  std::string name;
  SceneDescription scene;
};

// Processes that keep every core they are given busy, as `yes > /dev/null` does, until stopped.
class BusyProcesses {
 public:
  explicit BusyProcesses(int count) {
    for (int k = 0; k < count; ++k) {
      const pid_t pid = fork();
      if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        execlp("yes", "yes", static_cast<char*>(nullptr));
        _exit(127);
      }
      if (pid > 0) {
        pids_.push_back(pid);
      }
    }
    usleep(200000);  // let the scheduler spread them
  }
  BusyProcesses(const BusyProcesses&) = delete;
  BusyProcesses& operator=(const BusyProcesses&) = delete;
  ~BusyProcesses() {
    for (const pid_t pid : pids_) {
      kill(pid, SIGKILL);
    }
    for (const pid_t pid : pids_) {
      waitpid(pid, nullptr, 0);
    }
  }

 private:
  std::vector<pid_t> pids_;
};

// A step's time on `threads` threads: the median of `repeats` batches of `steps` steps, from a
// state 20 steps into the motion, taken as a render takes them (runs of at most 256 steps,
// run/frame_source.cpp).
double step_seconds(const Model& model, double dt, int threads, int steps, int repeats) {
  set_thread_count(threads);
  State state = initial_state(model, dt);
  advance_steps(model, dt, {}, state, 20);
  return median_seconds(repeats,
                        [&] {
                          for (int s = 0; s < steps; s += 256) {
                            advance_steps(model, dt, {}, state, std::min(256, steps - s));
                          }
                        }) /
         steps;
}

struct Row {
  std::string name;
  Index bars = 0;
  Index springs = 0;
  double idle[2] = {0.0, 0.0};  // s a step on 1 and 2 threads
  double busy[2] = {0.0, 0.0};
};

const char* verdict(bool met) {
  return met ? "met" : "NOT met";
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  using namespace dinam;
  std::string only = "wuson,cloth,lattice";
  int repeats = 5;
  int busy = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg.rfind("--models=", 0) == 0) {
      only = arg.substr(9);
    } else if (arg.rfind("--repeats=", 0) == 0) {
      repeats = std::max(1, std::atoi(arg.c_str() + 10));
    } else if (arg.rfind("--busy=", 0) == 0) {
      busy = std::max(0, std::atoi(arg.c_str() + 7));
    } else {
      fmt::print(stderr, "usage: {} [--models=wuson,cloth,lattice] [--repeats=N] [--busy=N]\n",
                 argv[0]);
      return 2;
    }
  }
  std::vector<BenchModel> models;
  if (only.find("wuson") != std::string::npos) {
    if (std::filesystem::exists(kWuson)) {
      models.push_back({"Wuson (assimp)", wuson_scene()});
    } else {
      fmt::print("{} is missing (Debian's assimp-testmodels): the Wuson is left out\n", kWuson);
    }
  }
  if (only.find("cloth") != std::string::npos) {
    models.push_back({"cloth 100 × 100", scale_scene(ScaleStructure::kCloth, 30000)});
  }
  if (only.find("lattice") != std::string::npos) {
    models.push_back({"wire lattice", scale_scene(ScaleStructure::kWireLattice, 50000)});
  }
  fmt::print("dinam thread scaling; {} cores, {} busy processes for the shared figures\n\n",
             sysconf(_SC_NPROCESSORS_ONLN), busy);

  std::vector<Row> rows;
  for (const BenchModel& bench : models) {
    const Model model = build_model(bench.scene);
    const double dt =
        choose_timestep(model, bench.scene.timestep, bench.scene.fps, bench.scene.timestep_loc).dt;
    Row row{bench.name, model.bar_count(), spring_count(model)};
    // Batches of about a quarter of a second on one idle thread.
    const double probe = step_seconds(model, dt, 1, 20, 1);
    const int steps = std::max(20, static_cast<int>(0.25 / probe));
    for (int t = 0; t < 2; ++t) {
      row.idle[t] = step_seconds(model, dt, t + 1, steps, repeats);
    }
    {
      const BusyProcesses load(busy);
      for (int t = 0; t < 2; ++t) {
        row.busy[t] = step_seconds(model, dt, t + 1, steps, repeats);
      }
    }
    const WorkSplit split = split_work(model, 2);
    fmt::print(
        "{:<16} {:6} bars {:6} springs, {} evaluated on both threads: idle {:.3f} / "
        "{:.3f} ms, busy {:.3f} / {:.3f} ms (1 / 2 threads)\n",
        row.name, row.bars, row.springs, split.shared_springs, 1e3 * row.idle[0], 1e3 * row.idle[1],
        1e3 * row.busy[0], 1e3 * row.busy[1]);
    rows.push_back(row);
  }

  fmt::print("\n{:<16} {:>7} {:>9} {:>9} {:>7} {:>9} {:>9} {:>9} {:>11}\n", "model", "bars",
             "idle 1T", "idle 2T", "2T gain", "busy 1T", "busy 2T", "busy/1T", "busy/idle");
  for (const Row& row : rows) {
    const double gain = row.idle[0] / row.idle[1];
    const double against_one = row.busy[1] / row.busy[0];
    const double against_idle = row.busy[1] / row.idle[1];
    fmt::print("{:<16} {:7} {:7.3f}ms {:7.3f}ms {:6.2f}× {:7.3f}ms {:7.3f}ms {:8.2f}× {:10.2f}×\n",
               row.name, row.bars, 1e3 * row.idle[0], 1e3 * row.idle[1], gain, 1e3 * row.busy[0],
               1e3 * row.busy[1], against_one, against_idle);
    fmt::print(
        "{:<16} targets: idle gain ≥ 1.8 {}; busy 2T ≤ busy 1T {}; busy 2T ≤ 2.5 × idle "
        "2T {}\n",
        "", verdict(gain >= 1.8), verdict(against_one <= 1.0), verdict(against_idle <= 2.5));
  }
  return 0;
}
