// What each feature of the look costs per 1280 × 720 frame (issue 14): the table of
// bench/notes/performance.md ("The look"). A plain program, one run prints it all:
//   cmake --build build --target bench_look_costs && build/bench/bench_look_costs
// --only=flag, wire or movies runs one part. Given the path of a dinam program it also times the
// 120-frame flag movie end to end at each quality; --before=PATH adds the same run of another dinam
// build (the one before this work), run alternately with this one so that both meet the same
// machine load. Each per-frame figure is the median of 9 draws in a warm renderer, on two subjects:
// the flag one second in, and a 100 000-bar wire scene (a 180 × 180 grid drawn as wires, 97 560
// bars and 32 761 joints).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "run/frame_source.hpp"
#include "dynamics/stability.hpp"
#include "median_time.hpp"
#include "model/model.hpp"
#include "render/osmesa_renderer.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

using Clock = std::chrono::steady_clock;

// A subject to draw: its list, one instant's positions and camera, and eight instants for blur.
struct Subject {
  std::string name;
  DrawList list;
  std::vector<FrameSample> instant;
  std::vector<FrameSample> blurred;
  std::vector<std::vector<Vec3f>> held;
};

Subject flag_subject() {
  SceneDescription scene = read_scene(std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/flag.yaml");
  scene.quality.motion_blur = {8, 0.5};
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const int frame = 21;  // one second in
  const SimulatedFrames frames =
      simulate_frames(model, timestep, frame, false, {}, &scene.quality.motion_blur);
  const FrameCameras cameras = frame_cameras(scene, model, frames);
  Subject s{"flag (245 nodes, 579 bars, textured cloth)",
            make_draw_list(scene, model, frames.motion),
            {},
            {},
            {}};
  s.held = frames.positions;
  s.held.insert(s.held.end(), frames.instants.begin(), frames.instants.end());
  const auto f = static_cast<std::size_t>(frame - 1);
  s.instant.push_back({&s.held[f], cameras.frames[f]});
  for (std::size_t i = 0; i < 8; ++i) {
    const std::size_t k = f * 8 + i;
    s.blurred.push_back({&s.held[frames.positions.size() + k], cameras.instants[k]});
  }
  return s;
}

// 97 560 bars drawn as wires from their rest positions; blur averages eight copies of them, each
// moved 5 mm further along x (what blur costs does not depend on how far they move, but
// instants that are all alike would be drawn once).
Subject wire_subject() {
  const SceneDescription scene =
      read_scene_text(R"(version: 1
duration: 1
camera: {position: [2.6, -4.2, 2.6], look_at: [0, 0, 1.8]}
objects:
  - name: lattice
    mesh:
      grid: {width: 3.6, height: 3.6, columns: 180, rows: 180, diagonals: one}
      rotation: [90, 0, 0]
      translation: [0, 0, 1.8]
    material: {density: 1200, youngs_modulus: 5.0e6, radius: 0.002}
    style: wire
    color: [0.75, 0.7, 0.6]
)",
                      std::filesystem::temp_directory_path() / "look_costs.yaml");
  const Model model = build_model(scene);
  Subject s{"100 000-bar wire scene (97 560 bars, 32 761 joints)", {}, {}, {}, {}};
  s.held.emplace_back();
  positions_for_render(model.node_initial_x, s.held.back());
  Bounds bounds;
  for (const Vec3f& p : s.held.back()) {
    bounds.add(p);
  }
  s.list = make_draw_list(scene, model, bounds);
  const RenderCamera camera{scene.camera.position.cast<float>(), scene.camera.look_at.cast<float>(),
                            Vec3f::UnitZ(), 40.0f};
  for (int k = 1; k <= 8; ++k) {
    std::vector<Vec3f> moved = s.held.front();
    for (Vec3f& p : moved) {
      p.x() += 0.005f * static_cast<float>(k);
    }
    s.held.push_back(std::move(moved));
  }
  s.instant.push_back({&s.held.front(), camera});
  for (std::size_t k = 1; k <= 8; ++k) {
    s.blurred.push_back({&s.held[k], camera});
  }
  return s;
}

struct Variant {
  std::string name;
  QualityPreset preset;
  std::function<void(RenderQualityDesc&)> change;
  bool blur = false;
};

double frame_seconds(const Subject& s, const RenderQualityDesc& quality, bool blur, int repeats) {
  RenderSettings settings{1280, 720, quality.samples,
                          quality.shadows ? quality.shadow_resolution : 0, quality.look};
  OsmesaRenderer renderer(settings);
  Image image;
  const std::vector<FrameSample>& samples = blur ? s.blurred : s.instant;
  renderer.render(s.list, samples, image);  // warm: uploads, shader compilation
  return median_seconds(repeats, [&] { renderer.render(s.list, samples, image); });
}

// `large`: the subject takes seconds a frame; fewer variants and draws.
void report_features(const Subject& s, bool large) {
  const auto none = [](RenderQualityDesc&) {};
  const std::vector<Variant> variants = {
      {"standard (the default)", QualityPreset::kStandard, none},
      {"draft", QualityPreset::kDraft, none},
      {"final, one instant", QualityPreset::kFinal, none},
      {"final with 8 blur instants", QualityPreset::kFinal, none, true},
      {"standard + soft shadows", QualityPreset::kStandard,
       [](RenderQualityDesc& q) { q.look.soft_shadows = true; }},
      {"standard + ambient occlusion", QualityPreset::kStandard,
       [](RenderQualityDesc& q) { q.look.ambient_occlusion = true; }},
      {"standard − sky light", QualityPreset::kStandard,
       [](RenderQualityDesc& q) { q.look.sky_light = false; }},
      {"standard − tone mapping", QualityPreset::kStandard,
       [](RenderQualityDesc& q) { q.look.tone_mapping = false; }},
      {"standard − shadows", QualityPreset::kStandard,
       [](RenderQualityDesc& q) { q.shadows = false; }},
      {"standard, no multisampling", QualityPreset::kStandard,
       [](RenderQualityDesc& q) { q.samples = 1; }},
      {"standard with 8 blur instants", QualityPreset::kStandard, none, true},
  };
  fmt::print("\n{} at 1280x720\n", s.name);
  fmt::print("| {:<32} | {:>10} | {:>12} |\n", "look", "ms a frame", "× standard");
  fmt::print("|{:-<34}|{:->12}|{:->14}|\n", "", "", "");
  double standard = 0.0;
  for (const Variant& v : variants) {
    if (large &&
        (v.name.find(" + ") != std::string::npos || v.name.find(" − ") != std::string::npos) &&
        v.name != "standard − shadows") {
      continue;
    }
    RenderQualityDesc quality = quality_preset(v.preset);
    v.change(quality);
    const double seconds = frame_seconds(s, quality, v.blur, large ? 5 : 9);
    standard = standard > 0.0 ? standard : seconds;
    fmt::print("| {:<32} | {:>10.1f} | {:>12.2f} |\n", v.name, 1e3 * seconds, seconds / standard);
  }
}

// The 120-frame flag movie, scene file to mp4, at each quality (medians of 3), this build and,
// alternately, the one before.
void report_movies(const std::string& dinam, const std::string& before) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "look_costs";
  std::filesystem::create_directories(folder);
  const std::filesystem::path scene = std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/flag.yaml";
  std::string text;
  {
    std::ifstream in(scene);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  struct Run {
    std::string name;
    std::string program;
    std::string quality;  // "" for the scene as shipped
    std::vector<double> seconds;
  };
  std::vector<Run> runs;
  if (!before.empty()) {
    runs.push_back({"before this work, the default", before, "", {}});
  }
  for (const char* quality : {"draft", "standard", "final"}) {
    runs.push_back({fmt::format("quality: {}", quality), dinam, quality, {}});
  }
  // Copies of the scene beside the runs' output, its asset paths made absolute.
  const std::string assets = "../assets/";
  for (std::size_t at = text.find(assets); at != std::string::npos; at = text.find(assets, at)) {
    const std::string absolute = (std::filesystem::path(DINAM_SOURCE_DIR) / "assets/").string();
    text.replace(at, assets.size(), absolute);
    at += absolute.size();
  }
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::string scene_text = text;
    if (runs[r].quality.empty()) {  // the build before this work knows no finishes
      for (std::size_t at = scene_text.find("    finish:"); at != std::string::npos;
           at = scene_text.find("    finish:", at)) {
        scene_text.erase(at, scene_text.find('\n', at) - at + 1);
      }
    }
    const std::string image = "image: {width: 1280, height: 720}";
    if (!runs[r].quality.empty()) {
      scene_text.replace(
          scene_text.find(image), image.size(),
          fmt::format("image: {{width: 1280, height: 720, quality: {}}}", runs[r].quality));
    }
    std::ofstream(folder / fmt::format("flag_{}.yaml", r)) << scene_text;
  }
  for (int repeat = 0; repeat < 3; ++repeat) {
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const std::string command = fmt::format("'{}' render '{}' -o '{}' -q", runs[r].program,
                                              (folder / fmt::format("flag_{}.yaml", r)).string(),
                                              (folder / "out").string());
      const auto start = Clock::now();
      if (std::system(command.c_str()) != 0) {
        fmt::print(stderr, "failed: {}\n", command);
        std::exit(1);
      }
      runs[r].seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
  }
  fmt::print("\nthe 120-frame flag movie, 1280x720, scene file to mp4 (median of 3)\n");
  for (Run& run : runs) {
    std::sort(run.seconds.begin(), run.seconds.end());
    fmt::print("  {:<32} {:6.2f} s\n", run.name, run.seconds[1]);
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace dinam

int main(int argc, char** argv) {
  std::string dinam;
  std::string before;
  std::string only;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg.rfind("--before=", 0) == 0) {
      before = arg.substr(9);
    } else if (arg.rfind("--only=", 0) == 0) {
      only = arg.substr(7);  // flag, wire or movies
    } else {
      dinam = arg;
    }
  }
  if (only.empty() || only == "flag") {
    dinam::report_features(dinam::flag_subject(), false);
  }
  if (only.empty() || only == "wire") {
    dinam::report_features(dinam::wire_subject(), true);
  }
  if (!only.empty() && only != "movies") {
    return 0;
  }
  if (!dinam.empty()) {
    dinam::report_movies(dinam, before);
  }
  return 0;
}
