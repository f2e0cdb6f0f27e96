#pragma once
// The program's commands, callable without the command line.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/cpu_share.hpp"

namespace dinam {

// Exit codes: 0 success, 1 any other failure (and snapshot differences), 2 bad usage or scene.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

struct RenderOptions {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> output;  // default: the scene's `output`
  std::optional<std::string> frames;            // "A-B"
  std::optional<std::string> size;              // "WxH"
  std::optional<std::string> movie;             // mp4, gif or none: overrides the scene
  std::optional<std::filesystem::path> cache;   // draw from this motion cache, simulating nothing
  bool quiet = false;
  bool energy_csv = false;  // write DIR/energy.csv, one row per frame
  bool force = false;       // run even when the memory estimate passes what is available, or the
                            // run-time estimate an hour
  bool preview = false;     // draft, small, every Nth frame: DIR/NAME_preview.gif and .png
};

// Simulates the scene (or reads its motion from a cache), writes DIR/frame_NNNN.png, DIR/
// frames.json and the movie. The frames are the same whether the whole motion is drawn at once or
// in ranges, from the scene or from its cache. Throws UserError for bad input (before anything is
// written) and RuntimeError for other failures. Returns the exit code: kExitFailure when the
// frames were written but ffmpeg is missing. With `preview`, run_preview.
int run_render(const RenderOptions& options);

// render --preview: the scene at draft quality, 320 pixels wide, about 30 frames spread over the
// motion (or --frames), as an animated GIF at the scene's pace and a contact sheet (PNG).
int run_preview(const RenderOptions& options);

struct SimulateOptions {
  std::filesystem::path scene;
  std::optional<std::filesystem::path> output;  // default: the scene's `output`/cache
  std::string formats = "pc2,usd";              // a list of pc2, mdd and usd
  bool quiet = false;
  bool energy = false;  // the energy report in the manifest and as energy.csv
  bool force = false;   // run even past the memory or run-time estimate's limits
};

// Simulates the scene once and writes its motion cache: a rest mesh (OBJ) and point caches (PC2,
// MDD) per object and manifest.json, all at once or not at all. Throws UserError for bad input.
int run_simulate(const SimulateOptions& options);

struct ModesOptions {
  std::filesystem::path scene;
  int count = 10;                               // the lowest modes to find
  std::optional<std::filesystem::path> output;  // the cache; default: the scene's `output`/modes
  bool quiet = false;
};

// Finds the scene's structure at rest under gravity (its `settle`, by default Newton's method),
// prints its lowest natural modes (frequency, period, the share of the free mass that moves with
// each in x, y and z) and writes them as a motion cache, one object per mode oscillating through
// one cycle, with modes.csv. Throws UserError for bad input.
int run_modes(const ModesOptions& options);

struct ViewOptions {
  std::filesystem::path cache;                  // a motion cache folder
  std::optional<std::filesystem::path> output;  // default: CACHE.html beside the folder
  int every = 1;                                // keep frames 1, 1 + every, …
  bool quiet = false;
};

// The page `view` writes without -o: the cache folder's name with .html, beside it.
std::filesystem::path default_view_path(const std::filesystem::path& cache);

// Writes one self-contained web page that plays the cache: an orbit camera, a timeline, play and
// pause, the frame number; surfaces shaded, wires at their drawn width. Throws UserError for a
// folder that is not a complete cache, or a page that would be too large (naming --every).
int run_view(const ViewOptions& options);

struct MovieOptions {
  std::filesystem::path folder;      // frames and frames.json, written by render
  std::optional<std::string> movie;  // mp4 or gif: overrides frames.json's choice
  bool quiet = false;
};

// Assembles the frames on disk into the movie, DIR/<name>.mp4 or .gif. Throws UserError naming the
// missing and extra frames by number, writing nothing, when the folder does not hold exactly the
// movie's frames.
int run_movie(const MovieOptions& options);

// Prints the model summary to stdout, as text or as one JSON object, with the run's estimates on
// the process's threads (core/thread_team.hpp) and `threads`' reason for their count. Throws
// UserError for a bad scene. With `energy`, the text says what energy balance the step gives and
// what step gives 0.1 %.
int run_info(const std::filesystem::path& scene, bool json = false,
             const ThreadChoice& threads = {}, bool energy = false);

struct SnapshotOptions {
  std::vector<std::filesystem::path> scenes;
  std::filesystem::path golden;       // folder of <name>_NNNN.png and tolerances.yaml
  std::optional<std::string> frames;  // "1,60,120" or ranges "1-3,9"; default first, middle, last
  std::string size = "320x180";
  std::optional<std::filesystem::path>
      output;           // actual/expected/diff images; default out/snapshot/<name>
  bool update = false;  // write the goldens (and the tolerance file) instead of failing on them
  // Limits given on the command line, over anything the tolerance file says.
  std::optional<int> threshold;
  std::optional<int> shift;
  std::optional<double> max_differing;
  std::optional<double> max_mean_error;
  std::optional<double> min_ssim;
  std::optional<std::filesystem::path> junit;   // a JUnit XML report of every frame
  std::optional<std::filesystem::path> report;  // one HTML page of every frame
  // The framing rule (visual/shot_framing.hpp): the least fraction of the picture's width or
  // height the subject must span, the whole subject inside; unchecked when not given.
  std::optional<double> framing;
  bool quiet = false;
};

// Renders the chosen frames of each scene and compares each with its golden under its tolerance
// (the golden folder's tolerances.yaml, snapshot/tolerance_file.hpp). Returns kExitOk when all
// match (or were written with update), kExitFailure otherwise, having written actual, expected
// and difference images of each that differs and printed their paths.
int run_snapshot(const SnapshotOptions& options);

}  // namespace dinam
