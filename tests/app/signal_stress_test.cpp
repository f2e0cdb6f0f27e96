// SIGINT and SIGTERM at random instants: 300 signals (50 for each of simulate and render with
// each integrator, snapshot --update and view) land wherever a run happens to be — reading the
// scene, importing a mesh in its child process, building the model, settling, stepping, drawing,
// encoding, writing goldens, reading a cache into a page. Every run must stop (none may go on to
// its end: each would take minutes), end by that signal, and leave no final output it had not
// finished, no temporary file and no process of its own behind.
//
// How soon it stops is not timed here (a clock in a test fails on a busy machine):
// bench/signal_latency.cpp measures it. The hang bound below only tells a stopped run from one
// that went on.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/png_file.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kSignalsPerCase = 10;  // the sanitizer build runs every phase several times slower
#else
constexpr int kSignalsPerCase = 50;
#endif
// The signal lands within this many milliseconds of the start: all of a run's phases before its
// frames are made, and a few seconds of frames.
constexpr int kLatestSignalMs = 1500;
// Polls of 10 ms before a run that has not ended counts as one that went on (60 s: the sanitizer
// build on a loaded machine is slow, and a run that ignored the signal takes minutes).
constexpr int kHangPolls = 6000;

// A 20 × 20 cloth from an OBJ file (so that the mesh is imported in a child process) and a rope;
// 100 s of motion, minutes of work for either integrator.
std::string cloth_and_rope(const std::string& integrator) {
  return R"(version: 1
name: stress
duration: 100
fps: 20
integrator: )" +
         integrator +
         R"(
objects:
  - name: cloth
    mesh: {file: cloth.obj}
    material: {preset: cotton}
    pinned: {box: {min: [-0.01, -1, 1.49], max: [1.01, 1, 1.51]}}
  - name: rope
    mesh: {polyline: {points: [[2, 0, 1.5], [2, 0, 1.0], [2, 0, 0.5]], segments: 4}}
    material: {preset: nylon_rope}
    pinned: {box: {min: [1.9, -1, 1.49], max: [2.1, 1, 1.51]}}
)";
}

// A rope of two bars for 8000 frames: simulated in a moment, so a render spends its time drawing
// the frames and streaming them to ffmpeg.
constexpr const char* kLongDrawing = R"(version: 1
name: stress
duration: 400
fps: 20
objects:
  - name: rope
    mesh: {polyline: {points: [[2, 0, 1.5], [2, 0, 1.0], [2.5, 0, 0.5]]}}
    material: {preset: nylon_rope}
    pinned: {box: {min: [1.9, -1, 1.49], max: [2.1, 1, 1.51]}}
)";

void write_cloth_mesh(const std::filesystem::path& path) {
  constexpr int kSide = 21;
  std::ofstream obj(path);
  for (int j = 0; j < kSide; ++j) {
    for (int i = 0; i < kSide; ++i) {
      obj << "v " << i / (kSide - 1.0) << " 0 " << 1.5 - j / (kSide - 1.0) << "\n";
    }
  }
  for (int j = 0; j + 1 < kSide; ++j) {
    for (int i = 0; i + 1 < kSide; ++i) {
      const int a = j * kSide + i + 1;
      obj << "f " << a << " " << a + 1 << " " << a + kSide + 1 << " " << a + kSide << "\n";
    }
  }
}

// The processes, other than zombies, whose command line mentions `text` (a run's own folder:
// dinam, its import child, its ffmpeg).
std::vector<std::string> processes_mentioning(const std::string& text) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
    std::ifstream file(entry.path() / "cmdline");
    std::stringstream bytes;
    bytes << file.rdbuf();
    std::string line = bytes.str();
    std::replace(line.begin(), line.end(), '\0', ' ');
    if (line.find(text) != std::string::npos) {
      found.push_back(entry.path().filename().string() + ": " + line);
    }
  }
  return found;
}

std::string read_text(const std::filesystem::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

class SignalStress : public ::testing::Test {
 protected:
  void SetUp() override { write_cloth_mesh(folder_.path() / "cloth.obj"); }

  // Runs `command` (simulate or render) on `scene_text` kSignalsPerCase times, each stopped by
  // SIGINT or SIGTERM at a random instant, and checks what each run did and left.
  void stop_at_random(const std::string& command, const std::string& scene_text) {
    const std::filesystem::path scene = folder_.path() / (command + ".yaml");
    std::ofstream(scene) << scene_text;
    const char* seed_text = std::getenv("DINAM_STRESS_SEED");
    const auto seed = seed_text != nullptr
                          ? static_cast<unsigned>(std::strtoul(seed_text, nullptr, 10))
                          : std::random_device{}();
    SCOPED_TRACE("DINAM_STRESS_SEED=" + std::to_string(seed));
    std::mt19937 random(seed);
    // `view` reads its cache in about 5 s here: its signals land within the first half second, so
    // that a machine ten times as fast still has a run to stop.
    std::uniform_int_distribution<int> instant_ms(0, command == "view" ? 500 : kLatestSignalMs);
    int by_handler = 0;
    for (int k = 0; k < kSignalsPerCase; ++k) {
      const int signal = k % 2 == 0 ? SIGTERM : SIGINT;
      const int delay_ms = instant_ms(random);
      const std::filesystem::path run = folder_.path() / (command + "_" + std::to_string(k));
      std::filesystem::create_directories(run);
      const std::filesystem::path output = run / (command == "simulate" ? "cache" : "out");
      const std::filesystem::path golden = run / "golden";
      std::vector<std::string> arguments =
          command == "simulate"
              ? std::vector<std::string>{"simulate", scene.string(), "-o", output.string(),
                                         "--force"}
              : std::vector<std::string>{"render", scene.string(), "-o",     output.string(),
                                         "--size", "160x90",       "--force"};
      if (command == "snapshot") {
        arguments = {"snapshot", scene.string(), "--golden",     golden.string(),
                     "--update", "--size",       "160x90",       "--frames",
                     "1-8000",   "-o",           output.string()};
      } else if (command == "view") {
        arguments = {"view", (folder_.path() / "cache").string(), "-o",
                     (output / "page.html").string()};
      }
      const pid_t pid = test::spawn_dinam(arguments, run / "log");
      ASSERT_NE(pid, 0);
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
      int status = 0;
      ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0)
          << "run " << k << " ended before its signal at " << delay_ms << " ms:\n"
          << read_text(run / "log");
      kill(pid, signal);
      bool ended = false;
      for (int poll = 0; poll < kHangPolls && !ended; ++poll) {
        ended = waitpid(pid, &status, WNOHANG) == pid;
        if (!ended) {
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      }
      if (!ended) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
      }
      const std::string log = read_text(run / "log");
      const std::string what = "run " + std::to_string(k) + ", " +
                               (signal == SIGTERM ? "SIGTERM" : "SIGINT") + " at " +
                               std::to_string(delay_ms) + " ms:\n" + log;
      EXPECT_TRUE(ended) << "went on after the signal; " << what;
      // Stopped by dinam's handler (exit 128 + signal), or by the signal's default action
      // before the handler was set (while nothing was being written).
      const bool handled = WIFEXITED(status) && WEXITSTATUS(status) == 128 + signal;
      const bool default_action = WIFSIGNALED(status) && WTERMSIG(status) == signal;
      EXPECT_TRUE(handled || default_action) << "status " << status << "; " << what;
      by_handler += handled ? 1 : 0;
      if (command == "simulate") {
        EXPECT_FALSE(std::filesystem::exists(output)) << "a cache was left; " << what;
        EXPECT_EQ(test::folder_entries(run), std::vector<std::string>{"log"})
            << "a temporary folder was left; " << what;
      } else if (command == "snapshot") {
        // The goldens written are whole pictures, none half-written; no report.
        EXPECT_EQ(test::temporary_files_in(golden), std::vector<std::string>{}) << what;
        EXPECT_EQ(test::temporary_files_in(output), std::vector<std::string>{}) << what;
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(golden, ec)) {
          if (entry.path().extension() == ".png") {
            EXPECT_NO_THROW(read_png(entry.path())) << entry.path() << "; " << what;
          }
        }
        if (handled) {
          EXPECT_NE(log.find(" written, each whole"), std::string::npos) << what;
        }
      } else if (command == "view") {
        // A signal after the page took its name (the run's last moments) leaves it whole.
        if (std::filesystem::exists(output / "page.html")) {
          const std::string page = read_text(output / "page.html");
          EXPECT_NE(page.rfind("</html>"), std::string::npos) << "a page cut short; " << what;
        }
        EXPECT_EQ(test::temporary_files_in(output), std::vector<std::string>{}) << what;
        if (handled) {
          EXPECT_NE(log.find("no page was written"), std::string::npos) << what;
          EXPECT_FALSE(std::filesystem::exists(output / "page.html")) << what;
        }
      } else {
        EXPECT_FALSE(std::filesystem::exists(output / "stress.mp4")) << what;
        EXPECT_EQ(test::temporary_files_in(output), std::vector<std::string>{}) << what;
      }
      // Its import child and its ffmpeg end with it (the system reaps them within moments).
      std::vector<std::string> left = processes_mentioning(run.string());
      for (int poll = 0; poll < 500 && !left.empty(); ++poll) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        left = processes_mentioning(run.string());
      }
      EXPECT_EQ(left, std::vector<std::string>{}) << what;
      std::filesystem::remove_all(run);
    }
    std::cout << command << ": " << kSignalsPerCase << " signals, " << by_handler
              << " honoured by dinam's handler, the rest by the default action\n";
  }

  test::TemporaryFolder folder_{"signal_stress"};
};

TEST_F(SignalStress, SimulateWithCentralDifferences) {
  stop_at_random("simulate", cloth_and_rope("central_difference"));
}

TEST_F(SignalStress, SimulateWithTheImplicitIntegrator) {
  stop_at_random("simulate", cloth_and_rope("implicit"));
}

TEST_F(SignalStress, RenderWithTheImplicitIntegrator) {
  stop_at_random("render", cloth_and_rope("implicit"));
}

TEST_F(SignalStress, RenderWhileDrawingAndEncoding) {
  stop_at_random("render", kLongDrawing);
}

// 8000 frames of a rope simulated in a moment, each drawn and written as a golden.
TEST_F(SignalStress, SnapshotUpdateWhileWritingGoldens) {
  stop_at_random("snapshot", kLongDrawing);
}

// A cache of a 30 × 30 cloth over 1600 frames, which `view` takes seconds to read and pack (a
// cloth's motion deflates slowly), made in seconds (half a minute under the sanitizer).
TEST_F(SignalStress, ViewWhileReadingTheCache) {
  const std::filesystem::path scene = folder_.path() / "cloth.yaml";
  std::ofstream(scene) << R"(version: 1
name: big
duration: 80
fps: 20
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 30, rows: 30}, rotation: [90, 0, 0]}
    material: {density: 1000, youngs_modulus: 1.0e5, radius: 0.002}
    pinned: {box: {min: [-1, -1, 0.49], max: [1, 1, 0.51]}}
)";
  const test::CommandResult made = test::run_dinam(
      {"simulate", scene.string(), "-o", (folder_.path() / "cache").string(), "--quiet"});
  ASSERT_EQ(made.exit_code, 0) << made.output;
  stop_at_random("view", "");
}

}  // namespace
}  // namespace dinam
