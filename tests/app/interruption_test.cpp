// SIGINT and SIGTERM stop a run before its end and leave only whole files: frames written stay,
// a movie or a cache half made goes, ffmpeg is stopped and reaped; SIGKILL leaves nothing that
// looks complete. (How soon it stops is not timed here: a clock in a test fails on a busy
// machine; bench/signal_latency.cpp measures it. dinam checks for a signal between frames, every
// few steps and in every long loop: core/stop_request.hpp.)
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "io/png_file.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::shell_quoted;

bool any_entry(const std::filesystem::path& folder,
               const std::function<bool(const std::string&)>& matches) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    if (matches(entry.path().filename().string())) {
      return true;
    }
  }
  return false;
}

struct Stopped {
  int status = 0;        // as waitpid gives it
  std::string messages;  // what dinam printed
};

// Runs dinam with `arguments`, waits (up to 120 s: the sanitizer build simulates several times
// slower) until `started(folder)` holds, sends `signal`
// and waits for the exit: up to 120 s, after which the run counts as one that went on (and is
// killed).
Stopped stop_while_running(const std::vector<std::string>& arguments, int signal,
                           const std::filesystem::path& folder,
                           const std::function<bool(const std::filesystem::path&)>& started) {
  const std::filesystem::path log = folder.parent_path() / (folder.filename().string() + ".log");
  const pid_t pid = test::spawn_dinam(arguments, log);
  EXPECT_NE(pid, 0);
  bool running = false;
  for (int i = 0; i < 4800 && !running; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    running = started(folder);
  }
  EXPECT_TRUE(running) << "the run never got going";
  kill(pid, signal);
  Stopped stopped;
  bool ended = false;
  for (int i = 0; i < 12000 && !ended; ++i) {
    ended = waitpid(pid, &stopped.status, WNOHANG) == pid;
    if (!ended) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  if (!ended) {
    kill(pid, SIGKILL);
    waitpid(pid, &stopped.status, 0);
  }
  EXPECT_TRUE(ended) << "it went on after the signal";
  std::stringstream text;
  text << std::ifstream(log).rdbuf();
  stopped.messages = text.str();
  return stopped;
}

class Interruption : public ::testing::Test {
 protected:
  std::filesystem::path path(const std::string& name) const { return folder_.path() / name; }
  test::TemporaryFolder folder_{"interrupt"};
};

TEST_F(Interruption, ARenderStopsBeforeItsEndKeepingWholeFramesAndNoMovie) {
  // A small cloth of 120 frames: its motion is simulated in a moment even under ASan, and then
  // drawing the frames at 640×360 takes seconds, the window in which the signal lands.
  const std::filesystem::path flag = path("cloth.yaml");
  std::ofstream(flag) << R"(version: 1
name: cloth
duration: 6
fps: 20
gravity: [0, 0, -9.81]
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 0.6, columns: 6, rows: 4}, rotation: [90, 0, 0], translation: [0, 0, 1.4]}
    material: {density: 1200, youngs_modulus: 2e6, radius: 0.001}
    pinned: {box: {min: [-0.01, -1, 1.39], max: [0.01, 1, 2.01]}}
)";
  for (const int signal : {SIGINT, SIGTERM}) {
    const std::filesystem::path out = path(signal == SIGINT ? "int" : "term");
    // Stopped once it has written a few frames, while ffmpeg is encoding the movie.
    const Stopped stopped =
        stop_while_running({"render", flag.string(), "-o", out.string(), "--size", "640x360"},
                           signal, out, [](const std::filesystem::path& folder) {
                             return std::filesystem::exists(folder / "frame_0003.png");
                           });
    ASSERT_TRUE(WIFEXITED(stopped.status)) << stopped.status;
    EXPECT_EQ(WEXITSTATUS(stopped.status), 128 + signal) << stopped.messages;
    EXPECT_NE(stopped.messages.find("frames were written to"), std::string::npos)
        << stopped.messages;
    EXPECT_NE(stopped.messages.find("no movie was made"), std::string::npos) << stopped.messages;
    EXPECT_FALSE(std::filesystem::exists(out / "cloth.mp4"));
    EXPECT_FALSE(any_entry(out,
                           [](const std::string& name) {
                             return name.find(".part") != std::string::npos ||
                                    name.find(".ffmpeg-log") != std::string::npos ||
                                    name.find(".tmp") != std::string::npos;
                           }))
        << "a temporary file was left in " << out;
    // Every frame left decodes whole, and no ffmpeg is left writing there (it was reaped).
    int kept = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
      EXPECT_NO_THROW(read_png(entry.path())) << entry.path();
      ++kept;
    }
    EXPECT_GE(kept, 3);
    EXPECT_LT(kept, 120);  // it stopped before its last frame
    const test::CommandResult ffmpeg = test::run_command("pgrep -a -x ffmpeg | grep -F " +
                                                         shell_quoted(out.string()) + " || true");
    EXPECT_EQ(ffmpeg.output, "") << "ffmpeg still runs: " << ffmpeg.output;
  }
}

TEST_F(Interruption, ASimulationLeavesNoCacheThatRenderAccepts) {
  // A 100 × 100 cloth for 100 s: far longer than the test waits.
  std::ofstream(path("big.yaml")) << R"(version: 1
duration: 100
fps: 10
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 100, rows: 100}, translation: [0, 0, 1]}
    material: {density: 800, youngs_modulus: 2.0e6, radius: 0.001}
)";
  // --force: its estimate passes the hour that is refused.
  const std::vector<std::string> simulate = {"simulate", path("big.yaml").string(), "-o",
                                             path("cache").string(), "--force"};
  const auto writing = [](const std::filesystem::path& cache) {  // its temporary folder exists
    return any_entry(cache.parent_path(),
                     [](const std::string& name) { return name.rfind("cache.part-", 0) == 0; });
  };
  // SIGTERM: dinam stops and removes its temporary folder.
  const Stopped terminated = stop_while_running(simulate, SIGTERM, path("cache"), writing);
  EXPECT_TRUE(WIFEXITED(terminated.status) && WEXITSTATUS(terminated.status) == 128 + SIGTERM)
      << terminated.status << terminated.messages;
  EXPECT_NE(terminated.messages.find("no cache was written"), std::string::npos)
      << terminated.messages;
  EXPECT_FALSE(any_entry(folder_.path(), [](const std::string& name) {
    return name.rfind("cache", 0) == 0 && name != "cache.log";
  }));

  // SIGKILL: no chance to clean up; what is left is no cache, and the next run clears it away.
  const Stopped killed = stop_while_running(simulate, SIGKILL, path("cache"), writing);
  EXPECT_TRUE(WIFSIGNALED(killed.status));
  EXPECT_FALSE(std::filesystem::exists(path("cache")));
  std::string leftover;
  for (const auto& entry : std::filesystem::directory_iterator(folder_.path())) {
    if (entry.is_directory()) {
      leftover = entry.path().string();
    }
  }
  ASSERT_FALSE(leftover.empty());
  for (const std::string& cache : {path("cache").string(), leftover}) {
    const test::CommandResult render = test::run_command(
        shell_quoted(DINAM_PROGRAM) + " render " + shell_quoted(path("big.yaml")) + " --cache " +
        shell_quoted(cache) + " -o " + shell_quoted(path("out")));
    EXPECT_EQ(render.exit_code, 2) << render.output;
  }
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

TEST_F(Interruption, ASignalStopsALongSettle) {
  // A 60 × 60 cloth asked to relax to a residual that rounding never lets it reach, for up to
  // 10⁴ s of relaxation: hours of work before the first frame. (Signals were looked at only
  // between frames, so this one waited for all of it.)
  std::ofstream(path("settle.yaml")) << R"(version: 1
duration: 1
fps: 10
settle: {method: relax, residual: 1e-12, duration: 10000}
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 60, rows: 60}, translation: [0, 0, 1]}
    material: {preset: cotton}
    pinned: {box: {min: [-0.01, -0.01, 0.99], max: [1.01, 0.01, 1.01]}}
)";
  int polls = 0;
  const Stopped stopped = stop_while_running(
      {"simulate", path("settle.yaml").string(), "-o", path("cache").string(), "--force"}, SIGTERM,
      path("cache"), [&](const std::filesystem::path&) { return ++polls >= 80; });
  EXPECT_TRUE(WIFEXITED(stopped.status) && WEXITSTATUS(stopped.status) == 128 + SIGTERM)
      << stopped.status << stopped.messages;
  EXPECT_NE(stopped.messages.find("no cache was written"), std::string::npos) << stopped.messages;
  EXPECT_FALSE(std::filesystem::exists(path("cache")));
}

}  // namespace
}  // namespace dinam
