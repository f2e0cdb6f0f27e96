// dinam snapshot: chosen frames of scenes drawn and compared with golden images under the
// tolerance kept beside them (snapshot/tolerance_file.hpp; goldens depend on the exact Mesa/LLVM
// build, so never byte for byte), with a JUnit XML and an HTML report for CI.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/stop_request.hpp"
#include "dynamics/stability.hpp"
#include "io/image_compare.hpp"
#include "io/png_file.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "run/frame_range.hpp"
#include "run/frame_source.hpp"
#include "scene/scene_description.hpp"
#include "snapshot/look_probe.hpp"
#include "snapshot/region_weights.hpp"
#include "snapshot/snapshot_report.hpp"
#include "snapshot/tolerance_file.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/frame_cameras.hpp"
#include "visual/frame_drawing.hpp"
#include "visual/shot.hpp"
#include "visual/shot_framing.hpp"
#include "visual/torn_drawing.hpp"

namespace dinam {
namespace {

// The command line's limits over the frame's.
ImageTolerance with_command_line(ImageTolerance limits, const SnapshotOptions& options) {
  limits.threshold = options.threshold.value_or(limits.threshold);
  limits.shift = options.shift.value_or(limits.shift);
  limits.max_differing_fraction = options.max_differing.value_or(limits.max_differing_fraction);
  limits.max_mean_error = options.max_mean_error.value_or(limits.max_mean_error);
  limits.min_ssim = options.min_ssim.value_or(limits.min_ssim);
  return limits;
}

// `frame` drawn with `list` and with `changed` (the subject's look changed,
// snapshot/look_probe.hpp) by `renderer`, the two compared under `limits` and the frame's regions;
// `drawn` is the first where the caller has it.
ImageComparison look_change_comparison(Renderer& renderer, const DrawList& list,
                                       const DrawList& changed, const Shot& shot,
                                       const SimulatedFrames& frames, int frame,
                                       const FrameTolerance& tolerance,
                                       const ImageTolerance& limits, Image drawn = {}) {
  if (drawn.rgba.empty()) {
    draw_frames(renderer, list, frames, shot.cameras, frame, frame,
                [&](int, const Image& image) { drawn = image; });
  }
  Image probe;
  draw_frames(renderer, changed, frames, shot.cameras, frame, frame,
              [&](int, const Image& image) { probe = image; });
  const std::vector<float> weights =
      region_weights(tolerance.regions, drawn.width, drawn.height,
                     shot.cameras.frames[static_cast<std::size_t>(frame - 1)]);
  return compare_images(probe, drawn, limits, weights);
}

// One object of a scene probed at --update: its points, the list with its look changed, and the
// frames whose goldens would pass that change.
struct ObjectProbe {
  std::string name;
  std::vector<std::uint8_t> chosen;  // its points among a frame's
  DrawList changed;
  std::vector<int> blind_frames;
  double most_differing = 0.0;   // the largest share of differing pixels the change made there
  double least_differing = 1.0;  // and the smallest
  ImageTolerance limits;         // of the first blind frame
  FrameTolerance tolerance;      // of the first blind frame
};

std::vector<ObjectProbe> object_probes(const Model& model, const DrawList& list) {
  std::vector<ObjectProbe> probes;
  for (const ModelObject& object : model.objects) {
    ObjectProbe probe;
    probe.name = object.name;
    probe.chosen.assign(static_cast<std::size_t>(model.node_count()), 0);
    std::fill_n(probe.chosen.begin() + object.first_node, object.node_count, std::uint8_t{1});
    probe.changed = with_changed_look(list, probe.chosen);
    probes.push_back(std::move(probe));
  }
  return probes;
}

// What would see an object's look change that `probe` found the goldens blind to, tried now on
// its first blind frame: a lower threshold where no pixel differed by more than it; else a larger
// --size (up to 4×), else a lower max_differing.
std::string what_sees_it(const SceneDescription& scene, const Shot& shot,
                         const SimulatedFrames& frames, const ObjectProbe& probe) {
  const int first = probe.blind_frames.front();
  const auto compare_at = [&](int scale, const ImageTolerance& limits) {
    SceneDescription sized = scene;
    sized.image_width *= scale;
    sized.image_height *= scale;
    OsmesaRenderer renderer(render_settings(sized));
    return look_change_comparison(renderer, shot.draw_list, probe.changed, shot, frames, first,
                                  probe.tolerance, limits);
  };
  if (probe.least_differing == 0.0) {
    for (const int threshold : {16, 12, 8}) {
      ImageTolerance lower = probe.limits;
      lower.threshold = threshold;
      if (!compare_at(1, lower).matches(lower)) {
        return fmt::format(
            "in frame {} no pixel differs by more than the threshold ({}); threshold: {} for the "
            "scene in the tolerance file sees it",
            first, probe.limits.threshold, threshold);
      }
    }
    return fmt::format(
        "in frame {} no pixel differs by more than the threshold ({}), nor by more than 8: the "
        "object's colour hardly shows in the picture (a metal, a shadowed or hidden part)",
        first, probe.limits.threshold);
  }
  for (int scale = 2; scale <= 4; ++scale) {
    const ImageComparison comparison = compare_at(scale, probe.limits);
    if (!comparison.matches(probe.limits)) {
      return fmt::format(
          "--size {}x{} sees it (the change fails frame {} there, {:.2f} % of the pixels "
          "differing); give that size both when updating and when comparing",
          scale * scene.image_width, scale * scene.image_height, first,
          100.0 * comparison.differing_fraction);
    }
  }
  // A thin wire covers the same share of the picture at any size: then the share allowed must
  // fall below what the change makes (half of it, so that the margin is the change's own).
  return fmt::format(
      "no --size up to {}x{} sees it; max_differing: {:.2g} for the scene in the tolerance file "
      "does (half the {:.2f} % the change makes at least), or weigh a box around the object there",
      4 * scene.image_width, 4 * scene.image_height, 0.5 * probe.least_differing,
      100.0 * probe.least_differing);
}

// At --update, where the goldens would not see an object's look change: a warning that says how
// thin the object is drawn and what would see it.
void warn_of_blind_goldens(const SceneDescription& scene, const Shot& shot,
                           const SimulatedFrames& frames, const ObjectProbe& probe) {
  const int first = probe.blind_frames.front();
  const float wire =
      median_wire_width(shot.draw_list, frames.at(first),
                        shot.cameras.frames[static_cast<std::size_t>(first - 1)], probe.chosen);
  const std::string thin = wire > 0.0f ? fmt::format("; its wires are drawn about {:.1f} px wide",
                                                     wire * static_cast<float>(scene.image_height))
                                       : "";
  fmt::print(stderr,
             "snapshot {}: warning: these goldens would not see object '{}' change: the green of "
             "its colours moved by {:g} passes in {} {} at {}x{} ({:.2f} % of the pixels differ "
             "at most, {:g} % allowed){}. {} (docs/snapshots.md, \"Thin subjects\")\n",
             scene.name, probe.name, kLookChange,
             probe.blind_frames.size() == 1 ? "frame" : "frames",
             fmt::join(probe.blind_frames, ", "), scene.image_width, scene.image_height,
             100.0 * probe.most_differing, 100.0 * probe.limits.max_differing_fraction, thin,
             what_sees_it(scene, shot, frames, probe));
}

// Draws the chosen frames of one scene and compares (or, with --update, writes) each. Returns the
// scene's name.
std::string check_scene(const SnapshotOptions& options, const ToleranceFile& tolerances,
                        const std::filesystem::path& scene_path,
                        std::vector<FrameResult>& results) {
  SceneDescription scene = read_scene(scene_path);
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

  // The whole motion frames the camera, so a frame looks as it does in the movie.
  const SimulatedFrames frames =
      simulate_frames(model, timestep, count, false, {}, &scene.quality.motion_blur);
  const Shot shot = make_shot(scene, model, frames, std::move(textures));
  const DrawList& draw_list = shot.draw_list;
  const FrameCameras& cameras = shot.cameras;
  OsmesaRenderer renderer(render_settings(scene));
  // For --framing: the list with the bars torn by the frame at hand hidden, brought up to date
  // frame by frame (`chosen` ascends), as draw_frames does.
  DrawList torn;
  std::size_t tears_hidden = 0;
  // For --update: each object's look changed, and the frames whose goldens would pass it.
  std::vector<ObjectProbe> probes =
      options.update ? object_probes(model, draw_list) : std::vector<ObjectProbe>{};
  if (options.framing && !frames.tears.empty()) {
    torn = draw_list;
  }

  for (const int frame : chosen) {
    stop_if_asked();  // between frames: a golden is written whole or not at all
    const auto start = std::chrono::steady_clock::now();
    FrameResult result;
    result.scene = scene.name;
    result.frame = frame;
    result.name = fmt::format("{}_{:04}", scene.name, frame);
    draw_frames(renderer, draw_list, frames, cameras, frame, frame,
                [&](int, const Image& drawn) { result.actual = drawn; });
    if (options.framing) {
      while (tears_hidden < frames.tears.size() && frames.tears[tears_hidden].frame <= frame) {
        hide_torn_bar(frames.tears[tears_hidden++], torn);
      }
      const PictureExtent extent = picture_extent(
          frames.tears.empty() ? draw_list : torn, frames.at(frame),
          cameras.frames[static_cast<std::size_t>(frame - 1)],
          static_cast<float>(scene.image_width) / static_cast<float>(scene.image_height));
      result.framing_checked = true;
      result.subject_width = extent.width();
      result.subject_height = extent.height();
      result.min_fill = static_cast<float>(*options.framing);
      result.framing_problem = framing_problem(extent, result.min_fill);
    }
    const std::filesystem::path golden = options.golden / (result.name + ".png");
    std::error_code ec;
    const bool have_golden = std::filesystem::is_regular_file(golden, ec);
    const FrameTolerance tolerance = tolerances.for_frame(ImageTolerance{}, scene.name, frame);
    result.limits = with_command_line(tolerance.limits, options);
    if (options.update) {
      create_folder(options.golden);
      write_png(golden, result.actual, PngOptions{9, true});  // goldens are kept: make them small
      result.outcome = FrameOutcome::kUpdated;
      result.detail = fmt::format("{} {}", have_golden ? "updated" : "created", golden.string());
      for (ObjectProbe& probe : probes) {
        const ImageComparison comparison =
            look_change_comparison(renderer, draw_list, probe.changed, shot, frames, frame,
                                   tolerance, result.limits, result.actual);
        if (comparison.matches(result.limits)) {
          if (probe.blind_frames.empty()) {
            probe.limits = result.limits;
            probe.tolerance = tolerance;
          }
          probe.blind_frames.push_back(frame);
          probe.most_differing = std::max(probe.most_differing, comparison.differing_fraction);
          probe.least_differing = std::min(probe.least_differing, comparison.differing_fraction);
        }
      }
    } else if (!have_golden) {
      result.outcome = FrameOutcome::kNoGolden;
      result.detail =
          fmt::format("no golden image {}; run with --update to create it", golden.string());
    } else {
      result.expected = read_regular_png(golden, "the golden image");
      result.has_regions = !tolerance.regions.empty();
      const std::vector<float> weights =
          region_weights(tolerance.regions, result.actual.width, result.actual.height,
                         cameras.frames[static_cast<std::size_t>(frame - 1)]);
      result.comparison = compare_images(result.actual, result.expected, result.limits, weights);
      result.outcome = result.comparison.matches(result.limits) ? FrameOutcome::kMatched
                                                                : FrameOutcome::kDiffers;
      if (result.outcome == FrameOutcome::kDiffers) {
        result.detail = result.comparison.failures(result.limits);
      }
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    switch (result.outcome) {
      case FrameOutcome::kUpdated:
        if (!options.quiet) {
          fmt::print("snapshot {}: {}\n", result.name, result.detail);
        }
        break;
      case FrameOutcome::kNoGolden:
        fmt::print(stderr, "snapshot {}: {}\n", result.name, result.detail);
        break;
      case FrameOutcome::kMatched:
        if (!options.quiet) {
          fmt::print(
              "snapshot {}: ok ({:.3f} % of pixels differ, mean error {:.3f}, SSIM {:.4f})\n",
              result.name, 100.0 * result.comparison.differing_fraction,
              result.comparison.mean_error, result.comparison.ssim);
        }
        break;
      case FrameOutcome::kDiffers: {
        create_folder(output);
        const std::filesystem::path actual_path = output / (result.name + "_actual.png");
        const std::filesystem::path expected_path = output / (result.name + "_expected.png");
        const std::filesystem::path diff_path = output / (result.name + "_diff.png");
        write_png(actual_path, result.actual);
        write_png(expected_path, result.expected);
        write_png(diff_path, result.comparison.difference);
        fmt::print(stderr,
                   "snapshot {}: DIFFERS{}: {}\n  ({:.3f} % of pixels differ, mean error {:.3f}, "
                   "SSIM {:.4f})\n  actual:     {}\n  expected:   {}\n  difference: {}\n",
                   result.name, result.comparison.same_size ? "" : " (size)", result.detail,
                   100.0 * result.comparison.differing_fraction, result.comparison.mean_error,
                   result.comparison.ssim, actual_path.string(), expected_path.string(),
                   diff_path.string());
        break;
      }
    }
    if (!result.framing_problem.empty()) {
      fmt::print(stderr, "snapshot {}: BADLY FRAMED: {}\n", result.name, result.framing_problem);
      result.detail += (result.detail.empty() ? "" : "; ") + result.framing_problem;
    } else if (result.framing_checked && !options.quiet) {
      fmt::print("snapshot {}: framed (the subject spans {:.0f} % × {:.0f} % of the picture)\n",
                 result.name, 100.0f * result.subject_width, 100.0f * result.subject_height);
    }
    results.push_back(std::move(result));
  }
  for (const ObjectProbe& probe : probes) {
    if (!probe.blind_frames.empty()) {
      warn_of_blind_goldens(scene, shot, frames, probe);
    }
  }
  return scene.name;
}

}  // namespace

int run_snapshot(const SnapshotOptions& options) {
  for (const auto& report : {options.junit, options.report}) {
    if (report) {
      check_output_name(*report);
      check_output_place(*report, OutputPlace::kBeside, "the report");
      make_parent_folder(*report, "the report");
    }
  }
  if (options.framing && !(*options.framing >= 0.0 && *options.framing <= 1.0)) {
    throw_user_error({},
                     "--framing must be a fraction of the picture from 0 to 1, e.g. 0.5; got {}",
                     *options.framing);
  }
  std::error_code ec;
  if (std::filesystem::exists(options.golden, ec) &&
      !std::filesystem::is_directory(options.golden, ec)) {
    throw_user_error({}, "--golden {} is a file; give the folder that holds the golden images",
                     options.golden.string());
  }
  if (options.update) {
    check_output_place(options.golden, OutputPlace::kInside, "--golden");
  }
  const ToleranceFile tolerances = read_tolerance_file(options.golden);
  std::vector<FrameResult> results;
  std::vector<std::string> names;
  // SIGINT and SIGTERM stop it between frames: what it wrote is whole, the reports unwritten.
  const StopOnSignals stop_on_signals;
  try {
    for (const std::filesystem::path& scene : options.scenes) {
      names.push_back(check_scene(options, tolerances, scene, results));
    }
    stop_if_asked();
  } catch (const Interrupted& e) {
    const auto written = std::count_if(results.begin(), results.end(), [](const FrameResult& r) {
      return r.outcome == FrameOutcome::kUpdated;
    });
    throw Interrupted(
        e.signal(),
        fmt::format("{} checked; {}no report written, no file half-written",
                    counted(static_cast<long long>(results.size()), "frame"),
                    options.update ? counted(static_cast<long long>(written), "golden image") +
                                         " written, each whole, the tolerance file as it was; "
                                   : ""));
  }
  if (options.update) {
    const std::string recorded =
        record_scenes(options.golden, names, with_command_line(ImageTolerance{}, options));
    if (!recorded.empty() && !options.quiet) {
      fmt::print("snapshot: {}\n", recorded);
    }
  }
  if (options.junit) {
    write_junit_report(*options.junit, results);
  }
  if (options.report) {
    write_html_report(*options.report, results);
    if (!options.quiet) {
      fmt::print("snapshot: the report is {}\n", options.report->string());
    }
  }
  const bool any_failed =
      std::any_of(results.begin(), results.end(), [](const FrameResult& r) { return failed(r); });
  return any_failed ? kExitFailure : kExitOk;
}

Command add_snapshot_command(CLI::App& app, std::optional<int>& threads) {
  auto options = std::make_shared<SnapshotOptions>();
  CLI::App* snapshot_command = app.add_subcommand(
      "snapshot",
      "Render chosen frames of scenes small and compare each with a golden PNG under the "
      "tolerance in the golden folder's tolerances.yaml (pixels that differ allowing an edge to "
      "move, mean error, SSIM; regions to ignore or weigh, per scene and frame); exit 1 on any "
      "difference, writing actual, expected and difference images, and JUnit XML and HTML "
      "reports when asked");
  snapshot_command->add_option("scenes", options->scenes, "Scene files (YAML)")->required();
  snapshot_command
      ->add_option("--golden", options->golden,
                   "Folder of golden images <name>_NNNN.png and their tolerances.yaml")
      ->required();
  snapshot_command->add_option("--frames", options->frames,
                               "Frames to check, e.g. 1,60,120, 1-3,9 or 1,50,last (default: "
                               "1,middle,last)");
  snapshot_command->add_option("--size", options->size, "Image size WxH")->default_val("320x180");
  add_optional_option(*snapshot_command, "-o,--output", options->output,
                      "Where differing frames' actual/expected/diff images go (default "
                      "out/snapshot/<name>)");
  snapshot_command->add_flag("--update", options->update,
                             "Write the rendered frames as the new goldens instead of comparing, "
                             "and the folder's tolerances.yaml where it has none (or lacks the "
                             "scene)");
  add_optional_option(*snapshot_command, "--junit", options->junit,
                      "Write a JUnit XML report of every frame to this file");
  add_optional_option(*snapshot_command, "--report", options->report,
                      "Write one self-contained HTML page of every frame (expected, actual, "
                      "difference, the measures) to this file");
  const ImageTolerance defaults;
  snapshot_command
      ->add_option("--threshold", options->threshold,
                   fmt::format("A pixel differs when a channel lies further than this (0-255) "
                               "from the other picture's values around it (default {}, or the "
                               "tolerance file's)",
                               defaults.threshold))
      ->check(CLI::Range(0, 255));
  snapshot_command
      ->add_option("--shift", options->shift,
                   fmt::format("How far, in pixels, an edge may move and still match (default {})",
                               defaults.shift))
      ->check(CLI::Range(0, 8));
  snapshot_command
      ->add_option("--max-differing", options->max_differing,
                   fmt::format("Largest fraction of differing pixels that still matches (default "
                               "{:g})",
                               defaults.max_differing_fraction))
      ->check(CLI::Range(0.0, 1.0));
  snapshot_command
      ->add_option("--max-mean-error", options->max_mean_error,
                   fmt::format("Largest mean channel error (0-255) that still matches (default "
                               "{:g})",
                               defaults.max_mean_error))
      ->check(CLI::Range(0.0, 255.0));
  snapshot_command
      ->add_option("--min-ssim", options->min_ssim,
                   fmt::format("Smallest structural similarity (SSIM, -1 to 1) that still "
                               "matches (default {:g})",
                               defaults.min_ssim))
      ->check(CLI::Range(-1.0, 1.0));
  snapshot_command
      ->add_option("--framing", options->framing,
                   "Also fail a frame whose subject (everything drawn but the ground) the "
                   "frame cuts, or that spans less than this fraction of both the picture's "
                   "width and height, e.g. 0.5")
      ->check(CLI::Range(0.0, 1.0));
  snapshot_command->add_flag("-q,--quiet", options->quiet, "Print only differences and errors");
  add_threads_option(*snapshot_command, threads);

  return {snapshot_command, [options](const ThreadChoice&) { return run_snapshot(*options); }};
}

}  // namespace dinam
