#include "cache/motion_cache_writer.hpp"

#include <fcntl.h>  // AT_FDCWD, for renameat2
#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <set>
#include <system_error>

#include "cache/obj_file.hpp"
#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/sha256.hpp"
#include "core/subject_box.hpp"
#include "core/version.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

constexpr const char* kManifestName = "manifest.json";
constexpr const char* kInstantsName = "motion_blur_instants.pc2";
constexpr const char* kUsdName = "scene.usda";

std::string host_name() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0) {
    return "host";
  }
  return cache_file_stem(name.data());
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::array<char, 32> text{};
  std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text.data();
}

// "DIR.part-HOST-" : the prefix of this machine's temporary folders for DIR.
std::string temporary_prefix(const std::filesystem::path& folder) {
  return folder.filename().string() + ".part-" + host_name() + "-";
}

// A cache the writer may replace: a folder holding a manifest, or an empty folder.
void check_replaceable(const std::filesystem::path& folder) {
  std::error_code ec;
  if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec)) {
    throw_user_error({}, "the cache folder {} is a file; give -o a folder name", folder.string());
  }
  check_output_folder_name(folder);  // never written or replaced through a link
  if (!std::filesystem::exists(folder, ec)) {
    return;
  }
  if (std::filesystem::is_regular_file(folder / kManifestName, ec) ||
      std::filesystem::is_empty(folder, ec)) {
    return;
  }
  throw_user_error({},
                   "{} exists and is not a motion cache (it has no {}); dinam replaces only "
                   "caches, so choose another -o folder or remove this one",
                   folder.string(), kManifestName);
}

// Temporary folders of runs on this machine that were killed before they could clean up.
void remove_abandoned(const std::filesystem::path& folder) {
  const std::string prefix = temporary_prefix(folder);
  std::error_code ec;
  const std::filesystem::path parent =
      folder.parent_path().empty() ? std::filesystem::path(".") : folder.parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) {
      continue;
    }
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      std::filesystem::remove_all(entry.path(), ec);
    }
  }
}

// Moves the complete cache `from` to `to`. An existing cache at `to` is swapped out in one step
// where the file system can (renameat2 RENAME_EXCHANGE), else moved aside first; then removed.
void move_into_place(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code ec;
  if (!std::filesystem::exists(to, ec)) {
    std::filesystem::rename(from, to, ec);
  } else if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) == 0) {
    std::filesystem::remove_all(from, ec);  // now the old cache
    ec.clear();
  } else {
    std::filesystem::path old = from;
    old += ".old";
    std::filesystem::rename(to, old, ec);
    if (!ec) {
      std::filesystem::rename(from, to, ec);
      std::error_code ignored;
      std::filesystem::remove_all(old, ignored);
    }
  }
  if (ec) {
    throw RuntimeError(fmt::format("cannot move the finished cache {} to {}: {}", from.string(),
                                   to.string(), ec.message()));
  }
}

// How an object is drawn when the scene does not say: its faces as a surface, its bars as wires
// where it has no faces, at its wire radius.
ObjectLook model_look(const Model& model, std::size_t o) {
  const ModelObject& object = model.objects[o];
  bool has_faces = false;
  for (Index f = 0; f < model.face_count() && !has_faces; ++f) {
    has_faces = model.node_object[model.face_nodes[model.face_offsets[f]]] == static_cast<Index>(o);
  }
  ObjectLook look;
  look.surface = has_faces;
  look.wires = !has_faces;
  look.wire_radius = static_cast<float>(object.wire_radius);
  return look;
}

// The object's map to its mesh file's vertices, where it has one that is not the identity.
void set_source_vertices(const Model& model, const ModelObject& object, CacheObjectEntry& entry) {
  if (object.source_vertex_count == 0 || model.node_source_vertex.empty()) {
    return;
  }
  entry.source_vertex_count = object.source_vertex_count;
  const auto first = model.node_source_vertex.begin() + object.first_node;
  const std::vector<Index> sources(first, first + object.node_count);
  bool identity = object.node_count == object.source_vertex_count;
  for (Index k = 0; identity && k < object.node_count; ++k) {
    identity = sources[k] == k;
  }
  if (!identity) {
    entry.source_vertices = sources;
  }
}

}  // namespace

std::string cache_file_stem(const std::string& object_name) {
  std::string stem;
  for (const char c : object_name) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_' || c == '.';
    stem.push_back(keep ? c : '_');
  }
  if (stem.empty() || stem.front() == '.') {
    stem.insert(0, "object");
  }
  // File systems take 255 bytes a name: a longer name keeps its start and ends in a digest of the
  // whole, so two long names that share their start still get files of their own.
  if (stem.size() > kLongestCacheStem) {
    stem = stem.substr(0, kLongestCacheStem - 17) + "-" + sha256_hex(object_name).substr(0, 16);
  }
  return stem;
}

MotionCacheWriter::MotionCacheWriter(const CacheRequest& request, const Model& model)
    : request_(request), node_count_(model.node_count()) {
  DINAM_CHECK(request_.pc2 || request_.mdd || request_.usd);
  check_replaceable(request_.folder);
  std::error_code ec;
  if (!request_.folder.parent_path().empty()) {
    std::filesystem::create_directories(request_.folder.parent_path(), ec);
  }
  remove_abandoned(request_.folder);
  temporary_ = request_.folder;
  temporary_.replace_filename(temporary_prefix(request_.folder) + std::to_string(getpid()));
  std::filesystem::remove_all(temporary_, ec);
  if (!std::filesystem::create_directory(temporary_, ec)) {
    throw RuntimeError(fmt::format("cannot create the cache folder {}: {}", temporary_.string(),
                                   ec ? ec.message() : "it exists"));
  }
  try {
    open_files(model);
  } catch (...) {
    discard();  // the destructor does not run for a constructor that throws
    throw;
  }
}

void MotionCacheWriter::open_files(const Model& model) {
  std::set<std::string> stems;
  std::vector<float> times(static_cast<std::size_t>(request_.frame_count));
  for (std::size_t k = 0; k < times.size(); ++k) {
    times[k] = static_cast<float>(static_cast<double>(k) / request_.fps);
  }
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ModelObject& object = model.objects[o];
    // Names that map to one stem ("a b" and "a_b") get the object's number after it, and more
    // where that too is taken.
    std::string stem = cache_file_stem(object.name);
    for (int more = 0; !stems.insert(stem).second; ++more) {
      stem = fmt::format("{}_{}{}", cache_file_stem(object.name), o,
                         more == 0 ? "" : "_" + std::to_string(more));
    }
    CacheObjectEntry entry{object.name,
                           object.first_node,
                           object.node_count,
                           object.bar_count,
                           stem + ".obj",
                           "",
                           "",
                           0,
                           {},
                           o < request_.looks.size() ? request_.looks[o] : model_look(model, o)};
    entry.look.color = object.color;
    if (!entry.look.texture.empty()) {
      // A copy in the cache, so that the folder carries its look wherever it goes (the USD
      // stage's material and `dinam view` read it there).
      const std::string name = stem + "_texture" + entry.look.texture.extension().string();
      std::error_code ec;
      std::filesystem::copy_file(entry.look.texture, temporary_ / name, ec);
      if (ec) {
        throw WriteError(fmt::format("cannot copy the texture {} into the cache: {}",
                                     entry.look.texture.string(), ec.message()));
      }
      entry.look.texture = name;
    }
    set_source_vertices(model, object, entry);
    write_obj(temporary_ / entry.obj, rest_mesh(model, o));
    ObjectFiles files{object.first_node, object.node_count, {}};
    PointCacheHeader header;
    header.point_count = object.node_count;
    header.sample_count = request_.frame_count;
    if (request_.pc2) {
      entry.pc2 = stem + ".pc2";
      header.format = PointCacheFormat::kPc2;
      files.caches.emplace_back(temporary_ / entry.pc2, header);
    }
    if (request_.mdd) {
      entry.mdd = stem + ".mdd";
      header.format = PointCacheFormat::kMdd;
      header.times = times;
      files.caches.emplace_back(temporary_ / entry.mdd, header);
    }
    entries_.push_back(std::move(entry));
    files_.push_back(std::move(files));
  }
  if (request_.usd) {
    std::vector<ObjectLook> looks;
    for (const CacheObjectEntry& entry : entries_) {
      looks.push_back(entry.look);
    }
    usd_ = std::make_unique<UsdStageWriter>(temporary_, kUsdName, model, looks, request_.fps,
                                            request_.frame_count);
  }
  frame_bounds_.reserve(static_cast<std::size_t>(request_.frame_count));
  if (!request_.instant_offsets.empty()) {
    // One sample per instant; PC2's start frame and rate place them evenly, as near as a header
    // can (the manifest holds each instant's exact step).
    const auto per_frame = static_cast<std::int32_t>(request_.instant_offsets.size());
    PointCacheHeader header;
    header.format = PointCacheFormat::kPc2;
    header.point_count = model.node_count();
    header.sample_count = per_frame * request_.frame_count;
    header.start_frame = 1.0f + static_cast<float>(request_.instant_offsets.front()) /
                                    static_cast<float>(request_.steps_per_frame);
    header.sample_rate = 1.0f / static_cast<float>(per_frame);
    instants_ = std::make_unique<PointCacheWriter>(temporary_ / kInstantsName, header);
  }
}

void MotionCacheWriter::discard() {
  files_.clear();  // closes the files before their folder goes
  instants_.reset();
  usd_.reset();
  std::error_code ec;
  std::filesystem::remove_all(temporary_, ec);
}

MotionCacheWriter::~MotionCacheWriter() {
  if (!committed_) {
    discard();
  }
}

void MotionCacheWriter::add_frame(const std::vector<Vec3f>& positions) {
  DINAM_CHECK(positions.size() == static_cast<std::size_t>(node_count_));
  FrameBounds bounds{positions.front(), positions.front()};
  for (const Vec3f& p : positions) {
    bounds.min = bounds.min.cwiseMin(p);
    bounds.max = bounds.max.cwiseMax(p);
  }
  subject_box(positions, bounds.subject_min, bounds.subject_max);
  frame_bounds_.push_back(bounds);
  for (ObjectFiles& files : files_) {
    for (PointCacheWriter& cache : files.caches) {
      cache.add_sample(positions.data() + files.first_node);
    }
  }
  if (usd_) {
    usd_->add_frame(positions);
  }
}

void MotionCacheWriter::add_instant(const std::vector<Vec3f>& positions) {
  DINAM_CHECK(instants_ != nullptr && positions.size() == static_cast<std::size_t>(node_count_));
  instants_->add_sample(positions.data());
}

void MotionCacheWriter::commit(CacheManifest manifest, const std::vector<float>& wire_radii) {
  DINAM_CHECK(frame_bounds_.size() == static_cast<std::size_t>(request_.frame_count));
  for (ObjectFiles& files : files_) {
    for (PointCacheWriter& cache : files.caches) {
      cache.close();
    }
  }
  if (instants_) {
    instants_->close();
    manifest.instants = {static_cast<int>(request_.instant_offsets.size()), request_.shutter,
                         request_.instant_offsets, kInstantsName};
  }
  DINAM_CHECK(wire_radii.empty() || wire_radii.size() == entries_.size());
  std::vector<ObjectLook> looks;
  for (std::size_t o = 0; o < entries_.size(); ++o) {
    if (!wire_radii.empty()) {
      entries_[o].look.wire_radius = wire_radii[o];
    }
    looks.push_back(entries_[o].look);
  }
  if (usd_) {
    usd_->write(looks);
    manifest.usd = usd_->file_name();
  }
  manifest.dinam_version = kVersion;
  manifest.created = utc_now();
  manifest.fps = request_.fps;
  manifest.frame_count = request_.frame_count;
  manifest.node_count = node_count_;
  manifest.objects = entries_;
  manifest.frame_bounds = frame_bounds_;
  write_manifest(temporary_ / kManifestName, manifest);
  check_output_folder_name(request_.folder);  // made a link while the run went? refuse it still
  move_into_place(temporary_, request_.folder);
  committed_ = true;
}

}  // namespace dinam
