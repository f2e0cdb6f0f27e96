// dinam snapshot: chosen frames of a scene drawn and compared with golden images under a
// tolerance (goldens depend on the exact Mesa/LLVM build, so never byte for byte).
#include <fmt/format.h>

#include <memory>

#include <filesystem>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "dynamics/stability.hpp"
#include "io/image_compare.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "run/frame_range.hpp"
#include "run/frame_source.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/frame_cameras.hpp"
#include "visual/frame_drawing.hpp"

namespace dinam {
namespace {

// "1,5-7,12" → {1, 5, 6, 7, 12}, each within 1..frame_count.
std::vector<int> parse_frame_list(const std::string& text, int frame_count) {
  std::set<int> frames;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const FrameRange range = parse_frame_range(item, frame_count);
    for (int f = range.first; f <= range.last; ++f) {
      frames.insert(f);
    }
    if (comma == std::string::npos) {
      break;
    }
    start = comma + 1;
  }
  return {frames.begin(), frames.end()};
}

}  // namespace

int run_snapshot(const SnapshotOptions& options) {
  SceneDescription scene = read_scene(options.scene);
  parse_image_size(options.size, scene.image_width, scene.image_height);
  const int count = scene.frame_count();
  const std::vector<int> chosen = options.frames ? parse_frame_list(*options.frames, count)
                                                 : std::vector<int>{1, (count + 1) / 2, count};
  const Model model = build_model_telling_warnings(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  std::vector<Image> textures = read_textures(scene);
  const std::filesystem::path output =
      options.output.value_or(std::filesystem::path("out/snapshot") / scene.name);
  check_output_place(output, OutputPlace::kInside, options.output ? "-o" : "the output folder");
  if (options.update) {
    check_output_place(options.golden, OutputPlace::kInside, "--golden");
  }

  // The whole motion frames the camera, so a frame looks as it does in the movie.
  const SimulatedFrames frames =
      simulate_frames(model, timestep, count, false, {}, &scene.quality.motion_blur);
  const DrawList draw_list = make_draw_list(scene, model, frames.motion, std::move(textures));
  const FrameCameras cameras = frame_cameras(scene, model, frames);
  OsmesaRenderer renderer(render_settings(scene));

  int failures = 0;
  Image image;
  for (const int frame : chosen) {
    draw_frames(renderer, draw_list, frames, cameras, frame, frame,
                [&](int, const Image& drawn) { image = drawn; });
    const std::string name = fmt::format("{}_{:04}", scene.name, frame);
    const std::filesystem::path golden = options.golden / (name + ".png");
    std::error_code ec;
    const bool have_golden = std::filesystem::is_regular_file(golden, ec);
    if (options.update) {
      create_folder(options.golden);
      write_png(golden, image, PngOptions{9, true});  // goldens are kept: make them small
      if (!options.quiet) {
        fmt::print("snapshot {}: {} {}\n", name, have_golden ? "updated" : "created",
                   golden.string());
      }
      continue;
    }
    if (!have_golden) {
      fmt::print(stderr, "snapshot {}: no golden image {}; run with --update to create it\n", name,
                 golden.string());
      ++failures;
      continue;
    }
    const Image expected = read_png(golden);
    const ImageComparison comparison = compare_images(image, expected, options.tolerance.threshold);
    if (comparison.matches(options.tolerance)) {
      if (!options.quiet) {
        fmt::print("snapshot {}: ok ({:.3f} % of pixels differ, mean error {:.3f})\n", name,
                   100.0 * comparison.differing_fraction, comparison.mean_error);
      }
      continue;
    }
    ++failures;
    create_folder(output);
    const std::filesystem::path actual_path = output / (name + "_actual.png");
    const std::filesystem::path expected_path = output / (name + "_expected.png");
    const std::filesystem::path diff_path = output / (name + "_diff.png");
    write_png(actual_path, image);
    write_png(expected_path, expected);
    write_png(diff_path, comparison.difference);
    fmt::print(stderr,
               "snapshot {}: DIFFERS{}: {:.3f} % of pixels differ by more than {} (allowed {:.3f} "
               "%), mean error {:.3f} (allowed {:.3f})\n  actual:     {}\n  expected:   {}\n  "
               "difference: {}\n",
               name, comparison.same_size ? "" : " (size)", 100.0 * comparison.differing_fraction,
               options.tolerance.threshold, 100.0 * options.tolerance.max_differing_fraction,
               comparison.mean_error, options.tolerance.max_mean_error, actual_path.string(),
               expected_path.string(), diff_path.string());
  }
  return failures == 0 ? kExitOk : kExitFailure;
}

Command add_snapshot_command(CLI::App& app, std::optional<int>& threads) {
  auto options = std::make_shared<SnapshotOptions>();
  CLI::App* snapshot_command = app.add_subcommand(
      "snapshot",
      "Render chosen frames small and compare each with a golden PNG under a tolerance; exit 1 "
      "on any difference, writing actual, expected and difference images");
  snapshot_command->add_option("scene", options->scene, "Scene file (YAML)")->required();
  snapshot_command
      ->add_option("--golden", options->golden, "Folder of golden images <name>_NNNN.png")
      ->required();
  snapshot_command->add_option("--frames", options->frames,
                               "Frames to check, e.g. 1,60,120 or 1-3,9 (default: first, middle "
                               "and last)");
  snapshot_command->add_option("--size", options->size, "Image size WxH")->default_val("320x180");
  add_optional_option(*snapshot_command, "-o,--output", options->output,
                      "Where differing frames' actual/expected/diff images go (default "
                      "out/snapshot/<name>)");
  snapshot_command->add_flag("--update", options->update,
                             "Write the rendered frames as the new goldens instead of comparing");
  snapshot_command
      ->add_option("--threshold", options->tolerance.threshold,
                   "A pixel differs when a channel differs by more than this (0-255)")
      ->default_val(options->tolerance.threshold)
      ->check(CLI::Range(0, 255));
  snapshot_command
      ->add_option("--max-differing", options->tolerance.max_differing_fraction,
                   "Largest fraction of differing pixels that still matches")
      ->default_val(options->tolerance.max_differing_fraction)
      ->check(CLI::Range(0.0, 1.0));
  snapshot_command
      ->add_option("--max-mean-error", options->tolerance.max_mean_error,
                   "Largest mean channel error (0-255) that still matches")
      ->default_val(options->tolerance.max_mean_error)
      ->check(CLI::Range(0.0, 255.0));
  snapshot_command->add_flag("-q,--quiet", options->quiet, "Print only differences and errors");
  add_threads_option(*snapshot_command, threads);

  return {snapshot_command, [options](const ThreadChoice&) { return run_snapshot(*options); }};
}

}  // namespace dinam
