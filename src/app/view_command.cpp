// `dinam view`: a motion cache as one self-contained web page that plays it (web/viewer.html).
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "app/command_line.hpp"
#include "app/command_support.hpp"
#include "app/commands.hpp"
#include "app/three_module.hpp"
#include "app/viewer_page.hpp"
#include "cache/motion_cache.hpp"
#include "core/base64.hpp"
#include "core/counted.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/regular_file.hpp"
#include "core/stop_request.hpp"
#include "visual/sharp_edges.hpp"

namespace dinam {
namespace {

using Json = nlohmann::json;

// The most frame data a page holds (16-bit positions, before deflate and base64): a browser
// decodes a page of this size in a few seconds; more is a page no one wants to open.
constexpr std::uint64_t kMostPageBytes = 256ull << 20;

// An object's faces (fanned by the page), lines and texture coordinates from its rest OBJ, as the
// cache wrote it, in the ids of the whole cache's points. The file is read as untrusted: each
// index must be a number of one of the object's `count` points (or of its `vt` lines), or the
// line is refused by its number.
struct ObjectElements {
  Json faces = Json::array();
  Json face_sizes = Json::array();
  Json lines = Json::array();
  Json uvs = Json::array();       // u, v of each `vt`, v up
  Json face_uvs = Json::array();  // each face corner's vt, where every corner has one
};

Index parse_id(const std::filesystem::path& obj, int number, const std::string& digits, Index count,
               const char* what) {
  long long id = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), id);
  if (error != std::errc() || end != digits.data() + digits.size() || id < 1 || id > count) {
    throw UserError(FileLoc{obj.string(), number, 1},
                    fmt::format("'{}' is not a {} of this object (1 to {}): the cache's rest mesh "
                                "was edited or damaged; simulate again",
                                digits, what, count));
  }
  return static_cast<Index>(id) - 1;
}

ObjectElements read_elements(const std::filesystem::path& obj, Index first, Index count) {
  RegularFileIn in(obj, "the cache's rest mesh");
  if (!in) {
    throw_user_error(FileLoc{obj.string()}, "cannot read the cache's rest mesh: {}",
                     std::strerror(in.open_error()));
  }
  ObjectElements elements;
  bool every_corner_has_uv = true;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.rfind("vt ", 0) == 0) {
      std::istringstream words(line.substr(3));
      double u = 0.0;
      double v = 0.0;
      if (!(words >> u >> v) || !std::isfinite(u) || !std::isfinite(v)) {
        throw UserError(FileLoc{obj.string(), number, 1},
                        "a texture coordinate that is not two numbers; simulate again");
      }
      elements.uvs.push_back(u);
      elements.uvs.push_back(v);
      continue;
    }
    if (line.size() < 2 || (line[0] != 'f' && line[0] != 'l') || line[1] != ' ') {
      continue;
    }
    std::istringstream words(line.substr(2));
    std::string word;
    std::vector<Index> ids;
    std::vector<Index> uv_ids;
    while (words >> word) {
      const std::size_t slash = word.find('/');
      ids.push_back(first + parse_id(obj, number, word.substr(0, slash), count, "point"));
      if (slash != std::string::npos && slash + 1 < word.size()) {
        const std::string uv = word.substr(slash + 1, word.find('/', slash + 1) - slash - 1);
        uv_ids.push_back(parse_id(obj, number, uv, static_cast<Index>(elements.uvs.size() / 2),
                                  "texture coordinate"));
      }
    }
    if (ids.size() < (line[0] == 'f' ? 3u : 2u)) {
      throw UserError(FileLoc{obj.string(), number, 1},
                      "a face needs three points and a line two; simulate again");
    }
    if (line[0] == 'f') {
      elements.face_sizes.push_back(ids.size());
      for (const Index id : ids) {
        elements.faces.push_back(id);
      }
      every_corner_has_uv = every_corner_has_uv && uv_ids.size() == ids.size();
      for (const Index id : uv_ids) {
        elements.face_uvs.push_back(id);
      }
    } else {
      for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
        elements.lines.push_back(ids[k]);
        elements.lines.push_back(ids[k + 1]);
      }
    }
  }
  if (!every_corner_has_uv) {
    elements.face_uvs = Json::array();
  }
  return elements;
}

// zlib's deflate of `size` bytes, as the browser's DecompressionStream("deflate") inflates them.
// Fed a megabyte at a time, so that a request to stop is honoured within one (a large cache's
// frames take seconds to deflate at level 9); the bytes are compress2's whatever the pieces.
std::string deflated(const void* data, std::size_t size) {
  constexpr std::size_t kPiece = std::size_t{1} << 20;
  z_stream stream{};
  DINAM_CHECK(deflateInit(&stream, 9) == Z_OK);
  struct Ender {
    z_stream& stream;
    ~Ender() { deflateEnd(&stream); }
  } ender{stream};
  std::string out(deflateBound(&stream, static_cast<uLong>(size)), '\0');
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const auto* bytes = static_cast<const Bytef*>(data);
  for (std::size_t at = 0;; at += kPiece) {
    stop_if_asked();
    const std::size_t piece = std::min(kPiece, size - std::min(at, size));
    stream.next_in = const_cast<Bytef*>(bytes + std::min(at, size));
    stream.avail_in = static_cast<uInt>(piece);
    const bool last = at + piece >= size;
    const int status = deflate(&stream, last ? Z_FINISH : Z_NO_FLUSH);
    DINAM_CHECK(last ? status == Z_STREAM_END : status == Z_OK);
    if (last) {
      break;
    }
  }
  out.resize(stream.total_out);
  return out;
}

// Each face corner's point as the page shares it between faces, for a surface shaded with sharp
// edges (`shading: auto`): the corners on either side of an edge whose faces meet at more than
// its sharp angle get points of their own (visual/sharp_edges.hpp, at the first frame's
// positions `x`), numbered from `x.size()`; the page keys its vertices, and so its normals, by
// them. The faces are fanned into triangles as the page fans them.
Json corner_keys(const ObjectElements& elements, double sharp_angle, const std::vector<Vec3>& x) {
  std::vector<Index> triangles;
  std::vector<Index> triangle_face;
  std::vector<std::size_t> triangle_corner;  // each triangle corner's face corner
  std::size_t at = 0;
  for (std::size_t f = 0; f < elements.face_sizes.size(); ++f) {
    const auto size = elements.face_sizes[f].get<std::size_t>();
    for (std::size_t k = 1; k + 1 < size; ++k) {
      for (const std::size_t corner : {at, at + k, at + k + 1}) {
        triangles.push_back(elements.faces[corner].get<Index>());
        triangle_corner.push_back(corner);
      }
      triangle_face.push_back(static_cast<Index>(f));
    }
    at += size;
  }
  split_at_sharp_edges(triangles, triangle_face, x, sharp_angle * std::numbers::pi / 180.0,
                       static_cast<Index>(x.size()));
  Json keys = elements.faces;
  for (std::size_t c = 0; c < triangles.size(); ++c) {
    keys[triangle_corner[c]] = triangles[c];
  }
  return keys;
}

// A part of the page: deflated, then in base64 (which holds no '<').
std::string deflated_base64(const void* data, std::size_t size) {
  const std::string packed = deflated(data, size);
  return base64(packed.data(), packed.size());
}

// A texture of the cache as a data URL the page loads without the network.
std::string texture_data_url(const std::filesystem::path& file) {
  RegularFileIn in(file, "the cache's texture");
  if (!in) {
    throw_user_error(FileLoc{file.string()}, "cannot read the cache's texture: {}; simulate again",
                     std::strerror(in.open_error()));
  }
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return "data:image/png;base64," + base64(bytes.data(), bytes.size());
}

// Where the scene's ground is, from the settings the manifest keeps (its height, 0 by default);
// null where the scene has none shown.
Json ground_height(const CacheManifest& manifest) {
  double height = 0.0;
  for (const MotionSetting& setting : manifest.motion_settings) {
    if (setting.key == "ground.visible" && setting.value == "false") {
      return nullptr;
    }
    if (setting.key == "ground.height") {
      char* end = nullptr;
      height = std::strtod(setting.value.c_str(), &end);
      if (end == setting.value.c_str() || !std::isfinite(height)) {
        height = 0.0;
      }
    }
  }
  return height;
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

namespace {

// The page, written whole; Interrupted between frames (run_view says what it left).
int write_view_page(const ViewOptions& options) {
  const MotionCache cache(options.cache);
  const std::filesystem::path output = options.output.value_or(default_view_path(options.cache));
  check_output_place(output, OutputPlace::kBeside, options.output ? "-o" : "the page");
  make_parent_folder(output, options.output ? "-o" : "the page");
  const CacheManifest& manifest = cache.manifest();
  std::vector<int> frames;
  for (int frame = 1; frame <= manifest.frame_count; frame += options.every) {
    frames.push_back(frame);
  }
  const std::uint64_t bytes =
      frames.size() * static_cast<std::uint64_t>(manifest.node_count) * 3 * sizeof(std::uint16_t);
  if (bytes > kMostPageBytes) {
    throw_user_error({},
                     "the page would hold {} MB of positions ({} frames of {} points); keep "
                     "every Nth frame with --every {} or more",
                     bytes >> 20, frames.size(), manifest.node_count,
                     options.every * ((bytes + kMostPageBytes - 1) / kMostPageBytes));
  }

  // The first frame's positions, where a surface's sharp edges are found.
  std::vector<Vec3> rest;
  if (std::any_of(manifest.objects.begin(), manifest.objects.end(),
                  [](const CacheObjectEntry& entry) {
                    return entry.look.surface && entry.look.shading == Shading::kAuto;
                  })) {
    const std::vector<std::vector<Vec3f>> first = cache.read_frames(1, 1);
    for (const Vec3f& p : first.front()) {
      rest.push_back(p.cast<double>());
    }
  }
  Json objects = Json::array();
  for (const CacheObjectEntry& entry : manifest.objects) {
    ObjectElements elements =
        read_elements(cache.folder() / entry.obj, entry.first_node, entry.node_count);
    if (!entry.look.surface) {  // drawn as wires only: its faces' sides are its bars
      for (std::size_t f = 0, at = 0; f < elements.face_sizes.size(); ++f) {
        const std::size_t size = elements.face_sizes[f].get<std::size_t>();
        for (std::size_t k = 0; k < size; ++k) {
          elements.lines.push_back(elements.faces[at + k]);
          elements.lines.push_back(elements.faces[at + (k + 1) % size]);
        }
        at += size;
      }
      elements = {Json::array(), Json::array(), elements.lines, Json::array(), Json::array()};
    }
    Json object = {{"name", entry.name},
                   {"color", {entry.look.color.x(), entry.look.color.y(), entry.look.color.z()}},
                   {"radius", entry.look.wire_radius},
                   {"faces", elements.faces},
                   {"face_sizes", elements.face_sizes},
                   {"lines", elements.lines},
                   {"uvs", elements.uvs},
                   {"face_uvs", elements.face_uvs}};
    if (!entry.look.texture.empty() && !elements.face_uvs.empty()) {
      object["texture"] = texture_data_url(cache.folder() / entry.look.texture);
    }
    object["shading"] = shading_name(entry.look.shading);
    object["corner_keys"] = entry.look.shading == Shading::kAuto && !elements.faces.empty()
                                ? corner_keys(elements, entry.look.sharp_angle, rest)
                                : Json::array();
    objects.push_back(std::move(object));
  }
  Vec3f low = manifest.frame_bounds.front().min;
  Vec3f high = manifest.frame_bounds.front().max;
  for (const FrameBounds& b : manifest.frame_bounds) {
    low = low.cwiseMin(b.min);
    high = high.cwiseMax(b.max);
  }
  // Positions quantised to 14 bits over the motion's box: a step of 1/16 383 of its size on each
  // axis (61 µm on a 1 m cloth), below a pixel at any distance that shows the whole motion; 16
  // bits would make a 100 × 100 cloth's page a fifth larger for nothing one can see.
  constexpr float kLevels = 16383.0f;
  const Vec3f quantum = (high - low) / kLevels;
  const Json meta = {
      {"name", manifest.scene_name},
      {"fps", manifest.fps},
      {"frame_count", manifest.frame_count},
      {"frames", frames},
      {"points", manifest.node_count},
      {"bounds", {{"min", {low.x(), low.y(), low.z()}}, {"max", {high.x(), high.y(), high.z()}}}},
      {"quantum",
       {{"origin", {low.x(), low.y(), low.z()}},
        {"step", {quantum.x(), quantum.y(), quantum.z()}}}},
      {"ground", ground_height(manifest)},
      {"objects", objects}};

  // Each frame, coordinate by coordinate: every point's change from the frame before (the first
  // from zero), modulo 2¹⁶, its low bytes then its high bytes. A smooth motion changes little
  // from frame to frame, so the high bytes are mostly 0 or 255 and deflate to almost nothing.
  // (A prediction from the two frames before deflates worse at 20 frames a second: a cloth's
  // motion is not that smooth from frame to frame.)
  const auto n = static_cast<std::size_t>(manifest.node_count);
  std::vector<std::uint8_t> packed;
  packed.reserve(frames.size() * n * 6);
  std::vector<std::uint16_t> before(3 * n, 0);
  for (const int frame : frames) {
    stop_if_asked();
    const std::vector<std::vector<Vec3f>> read = cache.read_frames(frame, frame);
    const std::vector<Vec3f>& at = read.front();
    for (int c = 0; c < 3; ++c) {
      const std::size_t plane = packed.size();
      packed.resize(plane + 2 * n);
      for (std::size_t p = 0; p < n; ++p) {
        const float units = quantum[c] > 0.0f ? (at[p][c] - low[c]) / quantum[c] : 0.0f;
        const auto q = static_cast<std::uint16_t>(std::lround(std::clamp(units, 0.0f, kLevels)));
        const auto change = static_cast<std::uint16_t>(q - before[c * n + p]);
        before[c * n + p] = q;
        packed[plane + p] = static_cast<std::uint8_t>(change & 0xff);
        packed[plane + n + p] = static_cast<std::uint8_t>(change >> 8);
      }
    }
  }

  stop_if_asked();
  std::string page = viewer_page_template();
  // Each part deflated and in base64, which holds no '<' (so no "</script>" can end its element
  // early, whatever an object's name). Names not UTF-8 are shown with U+FFFD.
  const std::string meta_text = meta.dump(-1, ' ', false, Json::error_handler_t::replace);
  replace_once(page, "/*DINAM_META*/", deflated_base64(meta_text.data(), meta_text.size()));
  replace_once(page, "/*DINAM_FRAMES*/", deflated_base64(packed.data(), packed.size()));
  const std::string three = three_module_source();
  replace_once(page, "/*DINAM_THREE*/", deflated_base64(three.data(), three.size()));
  stop_if_asked();  // the last chance before the page takes its name
  write_output_file(output, page, "the viewer page");
  if (!options.quiet) {
    fmt::print("dinam: {} of {} in {} ({:.1f} MB); open it in a web browser\n",
               counted(static_cast<long long>(frames.size()), "frame"), options.cache.string(),
               output.string(), static_cast<double>(page.size()) / 1e6);
  }
  return kExitOk;
}

}  // namespace

int run_view(const ViewOptions& options) {
  // SIGINT and SIGTERM stop it while it reads the cache: the page is written whole or not at all.
  const StopOnSignals stop_on_signals;
  try {
    return write_view_page(options);
  } catch (const Interrupted& e) {
    throw Interrupted(e.signal(), "no page was written (a page there before is as it was)");
  }
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
