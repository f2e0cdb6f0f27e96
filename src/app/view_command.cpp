// `dinam view`: a motion cache as one self-contained web page that plays it (web/viewer.html).
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/viewer_page.hpp"
#include "cache/motion_cache.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"

namespace dinam {
namespace {

using Json = nlohmann::json;

// The most frame data a page holds (float32 positions, before base64): a browser decodes a page
// of this size in a few seconds; more is a page no one wants to open.
constexpr std::uint64_t kMostPageBytes = 256ull << 20;

// An object's faces (fanned by the page) and lines from its rest OBJ, as the cache wrote it, in
// the ids of the whole cache's points. The file is read as untrusted: each index must be a number
// of one of the object's `count` points, or the line is refused by its number.
void add_elements(const std::filesystem::path& obj, Index first, Index count, Json& faces,
                  Json& face_sizes, Json& lines) {
  std::ifstream in(obj);
  if (!in) {
    throw_user_error(FileLoc{obj.string()}, "cannot read the cache's rest mesh: {}",
                     std::strerror(errno));
  }
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.size() < 2 || (line[0] != 'f' && line[0] != 'l') || line[1] != ' ') {
      continue;
    }
    std::istringstream words(line.substr(2));
    std::string word;
    std::vector<Index> ids;
    while (words >> word) {
      const std::string digits = word.substr(0, word.find('/'));
      long long id = 0;
      const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), id);
      if (error != std::errc() || end != digits.data() + digits.size() || id < 1 || id > count) {
        throw UserError(FileLoc{obj.string(), number, 1},
                        fmt::format("'{}' is not a point of this object (1 to {}): the cache's "
                                    "rest mesh was edited or damaged; simulate again",
                                    word, count));
      }
      ids.push_back(first + static_cast<Index>(id) - 1);
    }
    if (ids.size() < (line[0] == 'f' ? 3u : 2u)) {
      throw UserError(FileLoc{obj.string(), number, 1},
                      "a face needs three points and a line two; simulate again");
    }
    if (line[0] == 'f') {
      face_sizes.push_back(ids.size());
      for (const Index id : ids) {
        faces.push_back(id);
      }
    } else {
      for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
        lines.push_back(ids[k]);
        lines.push_back(ids[k + 1]);
      }
    }
  }
}

std::string base64(const unsigned char* data, std::size_t size) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve(4 * ((size + 2) / 3));
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t chunk = (std::uint32_t{data[i]} << 16) |
                                (i + 1 < size ? std::uint32_t{data[i + 1]} << 8 : 0u) |
                                (i + 2 < size ? std::uint32_t{data[i + 2]} : 0u);
    out.push_back(kDigits[(chunk >> 18) & 63]);
    out.push_back(kDigits[(chunk >> 12) & 63]);
    out.push_back(i + 1 < size ? kDigits[(chunk >> 6) & 63] : '=');
    out.push_back(i + 2 < size ? kDigits[chunk & 63] : '=');
  }
  return out;
}

void replace_once(std::string& text, std::string_view placeholder, const std::string& value) {
  const std::size_t at = text.find(placeholder);
  DINAM_CHECK(at != std::string::npos);
  text.replace(at, placeholder.size(), value);
}

}  // namespace

std::filesystem::path default_view_path(const std::filesystem::path& cache) {
  std::filesystem::path folder = cache;
  if (!folder.has_filename()) {
    folder = folder.parent_path();  // "out/cache/" names "out/cache"
  }
  return folder.string() + ".html";
}

int run_view(const ViewOptions& options) {
  const MotionCache cache(options.cache);
  const std::filesystem::path output = options.output.value_or(default_view_path(options.cache));
  check_output_place(output, OutputPlace::kBeside, options.output ? "-o" : "the page");
  const CacheManifest& manifest = cache.manifest();
  std::vector<int> frames;
  for (int frame = 1; frame <= manifest.frame_count; frame += options.every) {
    frames.push_back(frame);
  }
  const std::uint64_t bytes =
      frames.size() * static_cast<std::uint64_t>(manifest.node_count) * 3 * sizeof(float);
  if (bytes > kMostPageBytes) {
    throw_user_error({},
                     "the page would hold {} MB of positions ({} frames of {} points); keep "
                     "every Nth frame with --every {} or more",
                     bytes >> 20, frames.size(), manifest.node_count,
                     options.every * ((bytes + kMostPageBytes - 1) / kMostPageBytes));
  }

  Json objects = Json::array();
  for (const CacheObjectEntry& entry : manifest.objects) {
    Json faces = Json::array();
    Json face_sizes = Json::array();
    Json lines = Json::array();
    add_elements(cache.folder() / entry.obj, entry.first_node, entry.node_count, faces, face_sizes,
                 lines);
    if (!entry.look.surface) {  // drawn as wires only: its faces' sides are its bars
      for (std::size_t f = 0, at = 0; f < face_sizes.size(); ++f) {
        const std::size_t size = face_sizes[f].get<std::size_t>();
        for (std::size_t k = 0; k < size; ++k) {
          lines.push_back(faces[at + k]);
          lines.push_back(faces[at + (k + 1) % size]);
        }
        at += size;
      }
      faces = Json::array();
      face_sizes = Json::array();
    }
    objects.push_back(
        {{"name", entry.name},
         {"color", {entry.look.color.x(), entry.look.color.y(), entry.look.color.z()}},
         {"radius", entry.look.wire_radius},
         {"faces", faces},
         {"face_sizes", face_sizes},
         {"lines", lines}});
  }
  Vec3f low = manifest.frame_bounds.front().min;
  Vec3f high = manifest.frame_bounds.front().max;
  for (const FrameBounds& b : manifest.frame_bounds) {
    low = low.cwiseMin(b.min);
    high = high.cwiseMax(b.max);
  }
  const Json meta = {
      {"name", manifest.scene_name},
      {"fps", manifest.fps},
      {"frame_count", manifest.frame_count},
      {"frames", frames},
      {"points", manifest.node_count},
      {"bounds", {{"min", {low.x(), low.y(), low.z()}}, {"max", {high.x(), high.y(), high.z()}}}},
      {"objects", objects}};

  // Positions as little-endian float32, frame after frame.
  std::vector<float> values;
  values.reserve(bytes / sizeof(float));
  for (const int frame : frames) {
    const std::vector<std::vector<Vec3f>> read = cache.read_frames(frame, frame);
    for (const Vec3f& p : read.front()) {
      values.insert(values.end(), {p.x(), p.y(), p.z()});
    }
  }
  static_assert(std::endian::native == std::endian::little, "the page's floats are little-endian");

  std::string page = viewer_page_template();
  // No '<' may stand in the script element that holds the JSON: "</script>" would end it and
  // "<!--" open a comment that hides its end (an object of any name). '<' is only ever inside a
  // JSON string, where "\u003c" is the same character. Names not UTF-8 are shown with U+FFFD.
  std::string meta_text = meta.dump(-1, ' ', false, Json::error_handler_t::replace);
  for (std::size_t at = meta_text.find('<'); at != std::string::npos;
       at = meta_text.find('<', at)) {
    meta_text.replace(at, 1, "\\u003c");
  }
  replace_once(page, "/*DINAM_META*/", meta_text);
  replace_once(
      page, "/*DINAM_FRAMES*/",
      base64(reinterpret_cast<const unsigned char*>(values.data()), values.size() * sizeof(float)));
  write_output_file(output, page, "the viewer page");
  if (!options.quiet) {
    fmt::print("dinam: {} frames of {} in {} ({:.1f} MB); open it in a web browser\n",
               frames.size(), options.cache.string(), output.string(),
               static_cast<double>(page.size()) / 1e6);
  }
  return kExitOk;
}

Command add_view_command(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* view_command = app.add_subcommand(
      "view",
      "Write a motion cache as one web page that plays it (orbit, timeline, play/pause): open it "
      "in any browser, offline");
  view_command->add_option("cache", options->cache, "Motion cache folder (dinam simulate)")
      ->required();
  add_optional_option(*view_command, "-o,--output", options->output,
                      "The page to write (default: the cache folder's name with .html)");
  view_command->add_option("--every", options->every, "Keep every Nth frame (a smaller page)")
      ->default_val(options->every)
      ->check(CLI::Range(1, 100000));
  view_command->add_flag("-q,--quiet", options->quiet, "Print nothing but errors");

  return {view_command, [options](const ThreadChoice&) { return run_view(*options); }};
}

}  // namespace dinam
