#include "scene/pin_track_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/byte_size.hpp"
#include "core/error.hpp"
#include "core/memory_budget.hpp"
#include "io/point_cache.hpp"

namespace dinam {
namespace {

// A first sample further than this share of the mesh's size from the mesh as placed is warned of:
// the pins jump there at t = 0, and the bars to free nodes with them. Float32 samples of a mesh
// a few metres across round at 1e-7 of it; a mesh written at another frame is off by far more.
constexpr double kFirstSampleShare = 1e-3;

// The largest distance between the first sample and the mesh as placed, and the mesh's size.
std::pair<double, double> first_sample_offset(const PinMotionDesc& motion, const RawMesh& mesh) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  double worst = 0.0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    lo = lo.cwiseMin(mesh.vertices[v]);
    hi = hi.cwiseMax(mesh.vertices[v]);
    worst = std::max(worst, (motion.track[v] - mesh.vertices[v]).norm());
  }
  return {worst, mesh.vertices.empty() ? 0.0 : (hi - lo).norm()};
}

}  // namespace

void read_pin_track(YamlMap& motion, const std::filesystem::path& scene_folder, double frames,
                    ObjectDesc& object, std::vector<std::string>& warnings) {
  const FileLoc where = motion.loc("point_cache");
  const std::string key = motion.path("point_cache");
  if (motion.has("displacement") || motion.has("profile")) {
    throw_user_error(where,
                     "'{}' gives the pins' whole path: leave out 'displacement' and 'profile' "
                     "(they shake the pins along one direction instead)",
                     key);
  }
  std::filesystem::path file = motion.string("point_cache", "");
  file = file.is_absolute() ? file : scene_folder / file;
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".pc2" && extension != ".mdd") {
    throw_user_error(where,
                     "'{}' must name a point cache, a .pc2 file (Blender's, 3ds Max's) or an .mdd "
                     "file (LightWave's, Houdini's); got '{}'",
                     key, file.filename().string());
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw_user_error(where, "'{}': no file '{}' (a path relative to the scene's folder)", key,
                     file.string());
  }
  // The file's own errors are told at the key that names it.
  const auto at_the_key = [&](const UserError& e) {
    throw_user_error(where, "'{}': {}: {}", key, e.loc().to_string(), e.message());
  };
  PointCacheHeader header;
  try {
    header = read_point_cache_header(
        file, extension == ".pc2" ? PointCacheFormat::kPc2 : PointCacheFormat::kMdd, kExportAgain);
  } catch (const UserError& e) {
    at_the_key(e);
  }
  // The file's own list of vertices where dinam reads one (an OBJ's `v` lines: assimp splits a
  // vertex that faces share), else the mesh's, as `pinned: {indices}` counts them.
  const RawMesh& mesh = object.mesh;
  const bool by_source = !mesh.source_vertex.empty();
  const std::size_t vertices =
      by_source ? static_cast<std::size_t>(mesh.source_vertex_count) : mesh.vertices.size();
  if (static_cast<std::size_t>(header.point_count) != vertices) {
    throw_user_error(where,
                     "'{}': '{}' holds {} points a sample where {} has {} vertices: a point cache "
                     "must be written from the same mesh, one point per vertex in the mesh file's "
                     "order (a modifier that adds or removes vertices, such as Subdivision, makes "
                     "another mesh)",
                     key, file.filename().string(), header.point_count, object.mesh_source,
                     vertices);
  }
  if (header.sample_count == 0) {
    throw_user_error(where, "'{}': '{}' holds no sample", key, file.filename().string());
  }
  PinMotionDesc& pin_motion = object.pin_motion;
  // PC2 says how many frames apart its samples are; MDD's samples are one a frame (its table of
  // times is the exporter's frames over its fps, which the scene's fps takes the place of).
  pin_motion.frames_per_sample =
      header.format == PointCacheFormat::kPc2 ? static_cast<double>(header.sample_rate) : 1.0;
  if (!(pin_motion.frames_per_sample > 0.0) || !std::isfinite(pin_motion.frames_per_sample)) {
    throw_user_error(where, "'{}': '{}' gives its samples {} frames apart; it must be more than 0",
                     key, file.filename().string(), pin_motion.frames_per_sample);
  }
  if (by_source && std::find(mesh.source_vertex.begin(), mesh.source_vertex.end(), Index{-1}) !=
                       mesh.source_vertex.end()) {
    throw_user_error(where,
                     "'{}': some vertex of {} is not one of the file's own 'v' lines, so no point "
                     "of the cache can be matched to it; write the mesh again from the program "
                     "that wrote the cache",
                     key, object.mesh_source);
  }
  // The samples the run reaches (the last one within its frames, and the next, which the path
  // leans towards), not those of a longer animation: a cache of ten million samples for a
  // three-frame scene reads four.
  const double reached = std::floor(frames / pin_motion.frames_per_sample) + 2.0;
  const auto samples = static_cast<std::int32_t>(
      std::min(static_cast<double>(header.sample_count), std::max(reached, 1.0)));
  const std::uint64_t track_bytes =
      static_cast<std::uint64_t>(samples) * mesh.vertices.size() * sizeof(Vec3);
  if (const MemoryBudget budget = available_memory();
      budget.bytes > 0 && track_bytes > budget.bytes / 2) {
    throw_user_error(where,
                     "'{}': the {} samples of '{}' the run reaches ({} points each) would take {} "
                     "of memory, more than half of the {} available ({}); shorten the cache or "
                     "the scene's duration",
                     key, samples, file.filename().string(), header.point_count,
                     byte_size(track_bytes), byte_size(budget.bytes), budget.source);
  }
  std::ifstream in(file, std::ios::binary);
  std::vector<Vec3f> sample(vertices);
  pin_motion.track.reserve(mesh.vertices.size() * static_cast<std::size_t>(samples));
  for (std::int32_t s = 0; s < samples; ++s) {
    try {
      read_point_cache_sample(in, file, header, s, sample.data(), kExportAgain);
    } catch (const UserError& e) {
      at_the_key(e);
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const Vec3f& p = sample[by_source ? static_cast<std::size_t>(mesh.source_vertex[v]) : v];
      pin_motion.track.push_back(object.placement(p.cast<double>()));
    }
  }
  const auto [offset, size] = first_sample_offset(pin_motion, object.mesh);
  if (offset > kFirstSampleShare * size) {
    warnings.push_back(fmt::format(
        "{}: warning: object '{}': the first sample of '{}' lies up to {:.3g} m from the mesh as "
        "placed, so the pinned nodes jump there at t = 0; write the mesh at the cache's first "
        "frame, with the same placement",
        where.to_string(), object.name, file.filename().string(), offset));
  }
}

}  // namespace dinam
