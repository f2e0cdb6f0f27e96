#include "snapshot/tolerance_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <system_error>

#include "core/output_file.hpp"
#include "core/regular_file.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

// A region weighed more counts this many times unless it says.
constexpr float kDefaultWeight = 4.0f;

SnapshotRegion read_region(const YAML::Node& node, const std::string& file, const std::string& path,
                           bool ignored) {
  YamlMap map(node, file, path);
  SnapshotRegion region;
  region.loc = map.loc();
  const bool pixels = map.has("pixels");
  const bool box = map.has("box");
  if (pixels == box) {
    throw UserError(map.loc(), fmt::format("{} needs one of 'pixels: [x0, y0, x1, y1]' (the "
                                           "golden's pixels) or 'box: [[x, y, z], [x, y, z]]' "
                                           "(the scene's metres)",
                                           map.name()));
  }
  if (pixels) {
    const YAML::Node list = map.get("pixels");
    if (!list.IsSequence() || list.size() != 4) {
      throw UserError(map.loc("pixels"),
                      fmt::format("{} must be a list of four pixel positions [x0, y0, x1, y1]",
                                  map.path("pixels")));
    }
    std::array<int, 4> rect{};
    for (std::size_t i = 0; i < 4; ++i) {
      rect[i] = as_int(list[i], file, map.path("pixels"));
    }
    if (rect[0] < 0 || rect[1] < 0 || rect[2] <= rect[0] || rect[3] <= rect[1]) {
      throw UserError(map.loc("pixels"),
                      fmt::format("{} [{}, {}, {}, {}] holds no pixel: x0 < x1 and y0 < y1, from "
                                  "0 (x1 and y1 are excluded)",
                                  map.path("pixels"), rect[0], rect[1], rect[2], rect[3]));
    }
    region.pixels = rect;
  } else {
    const YAML::Node corners = map.get("box");
    if (!corners.IsSequence() || corners.size() != 2) {
      throw UserError(
          map.loc("box"),
          fmt::format("{} must be two corners [[x, y, z], [x, y, z]] in metres", map.path("box")));
    }
    const Vec3 a = as_vec3(corners[0], file, map.path("box"));
    const Vec3 b = as_vec3(corners[1], file, map.path("box"));
    region.box_low = a.cwiseMin(b);
    region.box_high = a.cwiseMax(b);
  }
  if (ignored) {
    region.weight = 0.0f;
  } else {
    const double weight = map.number("weight", kDefaultWeight);
    if (!(weight > 0.0 && weight <= 1000.0)) {
      throw UserError(map.loc("weight"),
                      fmt::format("{} must be above 0 and at most 1000 (to leave a region out, "
                                  "list it under 'ignore')",
                                  map.path("weight")));
    }
    region.weight = static_cast<float>(weight);
  }
  map.finish();
  return region;
}

// Reads the limits and regions of one level; `frames` (a scene's) takes the frames' levels.
ToleranceLevel read_level(YamlMap& map, std::map<int, ToleranceLevel>* frames) {
  ToleranceLevel level;
  const std::string& file = map.file();
  const auto limit = [&](const char* key, double low, double high, const char* what) {
    std::optional<double> value;
    if (map.has(key)) {
      value = as_double(map.get(key), file, map.path(key));
      if (!(*value >= low && *value <= high)) {
        throw UserError(map.loc(key), fmt::format("{} must be {} from {:g} to {:g}", map.path(key),
                                                  what, low, high));
      }
    }
    return value;
  };
  if (const auto v = limit("threshold", 0, 255, "a channel difference")) {
    level.threshold = static_cast<int>(*v);
  }
  if (const auto v = limit("shift", 0, 8, "a distance in pixels")) {
    level.shift = static_cast<int>(*v);
  }
  level.max_differing_fraction = limit("max_differing", 0, 1, "a fraction of the pixels");
  level.max_mean_error = limit("max_mean_error", 0, 255, "a mean channel error");
  level.min_ssim = limit("min_ssim", -1, 1, "a structural similarity");
  for (const auto& [key, ignored] : {std::pair{"ignore", true}, std::pair{"weigh", false}}) {
    if (!map.has(key)) {
      continue;
    }
    const YAML::Node list = map.get(key);
    if (!list.IsSequence()) {
      throw UserError(map.loc(key),
                      fmt::format("{} must be a list of regions, e.g. [{{pixels: [0, 0, 80, 20]}}]",
                                  map.path(key)));
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      level.regions.push_back(
          read_region(list[i], file, fmt::format("{}[{}]", map.path(key), i), ignored));
    }
  }
  if (frames != nullptr && map.has("frames")) {
    const YAML::Node node = map.get("frames");
    if (!node.IsMap()) {
      throw UserError(map.loc("frames"),
                      fmt::format("'{}' must be a map of frame numbers to their limits, e.g. "
                                  "{{120: {{max_differing: 0.01}}}}",
                                  map.path("frames")));
    }
    YamlMap frame_map(node, file, map.path("frames"));
    for (const auto& entry : node) {
      const std::string key = entry.first.Scalar();
      const int frame = as_int(entry.first, file, map.path("frames"));
      if (frame < 1) {
        throw UserError(loc_of(entry.first, file),
                        fmt::format("{}: frame {} does not exist; frames count from 1",
                                    map.path("frames"), frame));
      }
      frame_map.get(key);
      YamlMap level_map(entry.second, file, frame_map.path(key));
      (*frames)[frame] = read_level(level_map, nullptr);
    }
    frame_map.finish();
  }
  map.finish();
  return level;
}

void apply(const ToleranceLevel& level, FrameTolerance& tolerance) {
  ImageTolerance& limits = tolerance.limits;
  limits.threshold = level.threshold.value_or(limits.threshold);
  limits.shift = level.shift.value_or(limits.shift);
  limits.max_differing_fraction =
      level.max_differing_fraction.value_or(limits.max_differing_fraction);
  limits.max_mean_error = level.max_mean_error.value_or(limits.max_mean_error);
  limits.min_ssim = level.min_ssim.value_or(limits.min_ssim);
  tolerance.regions.insert(tolerance.regions.end(), level.regions.begin(), level.regions.end());
}

std::string read_text(const std::filesystem::path& path) {
  RegularFileIn in(path, "the tolerance file");
  if (!in) {
    throw UserError(FileLoc{path.string()}, "cannot open the tolerance file");
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string limits_text(const ImageTolerance& limits) {
  return fmt::format(
      "{{threshold: {}, shift: {}, max_differing: {:g}, max_mean_error: {:g}, "
      "min_ssim: {:g}}}",
      limits.threshold, limits.shift, limits.max_differing_fraction, limits.max_mean_error,
      limits.min_ssim);
}

// A scene's name as a YAML key: quoted unless it is plain letters, digits, '_', '-' and '.'.
std::string yaml_key(const std::string& name) {
  const bool plain = !name.empty() && name.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-.") == std::string::npos;
  if (plain) {
    return name;
  }
  std::string quoted = "\"";
  for (const char c : name) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
    }
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

FrameTolerance ToleranceFile::for_frame(const ImageTolerance& base, const std::string& scene,
                                        int frame) const {
  FrameTolerance tolerance{base, {}};
  apply(defaults, tolerance);
  if (const auto found = scenes.find(scene); found != scenes.end()) {
    apply(found->second.scene, tolerance);
    if (const auto at = found->second.frames.find(frame); at != found->second.frames.end()) {
      apply(at->second, tolerance);
    }
  }
  return tolerance;
}

ToleranceFile read_tolerance_file(const std::filesystem::path& folder) {
  ToleranceFile file;
  file.path = folder / kToleranceFileName;
  std::error_code ec;
  if (!std::filesystem::exists(file.path, ec)) {
    return file;
  }
  file.exists = true;
  const std::string name = file.path.string();
  const YAML::Node root = parse_yaml(read_text(file.path), file.path);
  if (!root || root.IsNull()) {
    return file;
  }
  check_no_duplicate_keys(root, name);
  YamlMap top(root, name, "");
  const int version = top.integer("version", 1);
  if (version != 1) {
    throw UserError(top.loc("version"),
                    fmt::format("tolerance file version {} is not known; this dinam reads "
                                "version 1",
                                version));
  }
  if (top.has("default")) {
    YamlMap defaults(top.get("default"), name, "default");
    file.defaults = read_level(defaults, nullptr);
  }
  if (top.has("scenes")) {
    const YAML::Node scenes = top.get("scenes");
    if (!scenes.IsMap() && !scenes.IsNull()) {
      throw UserError(top.loc("scenes"),
                      "'scenes' must be a map of scene names to their limits, e.g. "
                      "{flag: {min_ssim: 0.98}}");
    }
    YamlMap scene_map(scenes, name, "scenes");
    for (const auto& entry : scenes) {
      if (!entry.first.IsScalar() || entry.first.Scalar().empty()) {
        throw UserError(loc_of(entry.first, name),
                        "a scene under 'scenes' is named by its name as text (its 'name', or "
                        "its file's name), not an empty key, a list or a map");
      }
      const std::string scene = entry.first.Scalar();
      scene_map.get(scene);
      SceneTolerances& tolerances = file.scenes[scene];
      if (entry.second.IsNull()) {
        continue;  // `flag:` with nothing: the defaults
      }
      YamlMap level(entry.second, name, scene_map.path(scene));
      tolerances.scene = read_level(level, &tolerances.frames);
    }
    scene_map.finish();
  }
  top.finish();
  return file;
}

std::string record_scenes(const std::filesystem::path& folder,
                          const std::vector<std::string>& scenes, const ImageTolerance& limits) {
  const ToleranceFile file = read_tolerance_file(folder);
  if (!file.exists) {
    std::string text = fmt::format(
        "# The tolerances `dinam snapshot` checks the goldens in this folder under (the limits "
        "each\n# frame may reach; `dinam snapshot --help` and docs/snapshots.md say what each "
        "means).\n# A scene, or a frame under its `frames`, may set its own limits and regions "
        "to\n# `ignore` or `weigh` more.\nversion: 1\ndefault: {}\nscenes:\n",
        limits_text(limits));
    for (const std::string& scene : scenes) {
      text += fmt::format("  {}: {{}}\n", yaml_key(scene));
    }
    write_output_file(file.path, text, "the tolerance file");
    return fmt::format("wrote {} (the default limits, {} scene{})", file.path.string(),
                       scenes.size(), scenes.size() == 1 ? "" : "s");
  }
  std::vector<std::string> missing;
  for (const std::string& scene : scenes) {
    if (file.scenes.count(scene) == 0) {
      missing.push_back(scene);
    }
  }
  if (missing.empty()) {
    return "";
  }
  // Appended only where the file ends inside its `scenes:` map (as dinam writes it): the last
  // line at the left margin that is not a comment is `scenes:`.
  const std::string text = read_text(file.path);
  std::istringstream lines(text);
  std::string line;
  std::string last_top;
  while (std::getline(lines, line)) {
    if (!line.empty() && line[0] != ' ' && line[0] != '#') {
      last_top = line;
    }
  }
  if (last_top.rfind("scenes:", 0) != 0 || last_top.find('{') != std::string::npos) {
    return "";
  }
  std::string added = text;
  if (!added.empty() && added.back() != '\n') {
    added += '\n';
  }
  for (const std::string& scene : missing) {
    added += fmt::format("  {}: {{}}\n", yaml_key(scene));
  }
  write_output_file(file.path, added, "the tolerance file");
  return fmt::format("added {} to {}", fmt::join(missing, ", "), file.path.string());
}

}  // namespace dinam
