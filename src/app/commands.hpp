#pragma once
// The program's commands, callable without the command line (tests use them directly).
#include <filesystem>
#include <optional>
#include <string>

namespace dinam {

// Exit codes: 0 success, 1 any other failure, 2 bad usage or a bad scene.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

struct RenderOptions {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> output;  // default: the scene's `output`
  std::optional<std::string> frames;            // "A-B"
  std::optional<std::string> size;              // "WxH"
  bool video = true;
  bool quiet = false;
  bool energy_csv = false;  // write DIR/energy.csv, one row per frame
};

// Simulates the scene, writes DIR/frame_NNNN.png and DIR/<name>.mp4. Throws UserError for bad
// input (before anything is written) and RuntimeError for other failures. Returns the exit code:
// kExitFailure when the frames were written but ffmpeg is missing.
int run_render(const RenderOptions& options);

// Prints the model summary to stdout. Throws UserError for a bad scene.
int run_info(const std::filesystem::path& scene);

}  // namespace dinam
