#include "cache/motion_cache.hpp"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <map>

#include "core/error.hpp"
#include "core/regular_file.hpp"
#include "core/version.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// "a: 1 in the cache, 2 in the scene; b: only in the scene (3); …", at most `shown` of them.
std::string settings_difference(const std::vector<MotionSetting>& cached,
                                const std::vector<MotionSetting>& current) {
  std::map<std::string, std::string> old_values;
  for (const MotionSetting& s : cached) {
    old_values[s.key] = s.value;
  }
  std::vector<std::string> differences;
  for (const MotionSetting& s : current) {
    const auto found = old_values.find(s.key);
    if (found == old_values.end()) {
      differences.push_back(fmt::format("{}: not in the cache's scene, {} now", s.key, s.value));
    } else {
      if (found->second != s.value) {
        differences.push_back(
            fmt::format("{}: {} in the cache, {} now", s.key, found->second, s.value));
      }
      old_values.erase(found);
    }
  }
  for (const MotionSetting& s : cached) {
    if (old_values.count(s.key) != 0) {
      differences.push_back(fmt::format("{}: {} in the cache, absent now", s.key, s.value));
    }
  }
  constexpr std::size_t kShown = 6;
  std::string text;
  for (std::size_t i = 0; i < differences.size() && i < kShown; ++i) {
    text += "\n  " + differences[i];
  }
  if (differences.size() > kShown) {
    text += fmt::format("\n  … and {} more", differences.size() - kShown);
  }
  return text;
}

// A point cache of the cache's folder, opened without following a link.
PointCacheHeader read_cache_header(const std::filesystem::path& path, PointCacheFormat format,
                                   const std::string& what) {
  RegularFileIn in(path, what);
  if (!in) {
    throw UserError(FileLoc{path.string()}, fmt::format("cannot open {}: {}; simulate again", what,
                                                        std::strerror(in.open_error())));
  }
  return read_point_cache_header(in, in.size(), path, format);
}

}  // namespace

MotionCache::MotionCache(std::filesystem::path folder) : folder_(std::move(folder)) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder_, ec)) {
    throw_user_error(FileLoc{folder_.string()},
                     "there is no such folder, so no motion cache there; make one with 'dinam "
                     "simulate SCENE -o {}'",
                     folder_.string());
  }
  manifest_ = read_manifest(folder_ / "manifest.json");
  for (const CacheObjectEntry& entry : manifest_.objects) {
    if (entry.pc2.empty() && entry.mdd.empty()) {
      throw_user_error(FileLoc{folder_.string()},
                       "the cache holds its motion as a USD stage alone ({}, made with --format "
                       "usd), and dinam draws from point caches; simulate again with --format "
                       "pc2,usd to have both",
                       manifest_.usd);
    }
    const bool pc2 = !entry.pc2.empty();
    ObjectCache cache;
    cache.path = folder_ / (pc2 ? entry.pc2 : entry.mdd);
    cache.header =
        read_cache_header(cache.path, pc2 ? PointCacheFormat::kPc2 : PointCacheFormat::kMdd,
                          "the cache's point cache");
    if (cache.header.point_count != entry.node_count ||
        cache.header.sample_count != manifest_.frame_count) {
      throw UserError(FileLoc{cache.path.string()},
                      fmt::format("the point cache holds {} samples of {} points where the "
                                  "manifest promises {} of {}; simulate again",
                                  cache.header.sample_count, cache.header.point_count,
                                  manifest_.frame_count, entry.node_count));
    }
    objects_.push_back(std::move(cache));
  }
  if (manifest_.instants.per_frame > 0) {
    instants_.path = folder_ / manifest_.instants.pc2;
    instants_.header = read_cache_header(instants_.path, PointCacheFormat::kPc2,
                                         "the cache's motion blur instants");
    if (instants_.header.point_count != manifest_.node_count ||
        instants_.header.sample_count != manifest_.instants.per_frame * manifest_.frame_count) {
      throw UserError(FileLoc{instants_.path.string()},
                      "the motion blur instants do not match the manifest; simulate again");
    }
  }
}

void MotionCache::check_scene(const SceneDescription& scene) const {
  const std::string again = fmt::format("simulate again: dinam simulate {} -o {}",
                                        scene.source.string(), folder_.string());
  const FileLoc loc{scene.source.string()};
  if (manifest_.dinam_version != kVersion) {
    throw UserError(loc, fmt::format("the cache {} was made by dinam {}, and this is dinam {}, "
                                     "which may move the scene differently; {}",
                                     folder_.string(), manifest_.dinam_version, kVersion, again));
  }
  if (manifest_.motion_settings == scene.motion_settings) {
    return;
  }
  const std::string difference =
      settings_difference(manifest_.motion_settings, scene.motion_settings);
  if (manifest_.scene_path != canonical_scene_path(scene.source)) {
    throw UserError(loc, fmt::format("the cache {} was made from another scene, {} ('{}'), whose "
                                     "motion differs from this one's:{}\n{}",
                                     folder_.string(), manifest_.scene_path, manifest_.scene_name,
                                     difference, again));
  }
  throw UserError(loc, fmt::format("the scene has changed since the cache {} was made ({}), in "
                                   "settings that change the motion (only edits to the camera, "
                                   "image, light, colours and output keep a cache):{}\n{}",
                                   folder_.string(), manifest_.created, difference, again));
}

std::optional<std::string> MotionCache::motion_blur_shortfall(const SceneDescription& scene) const {
  const MotionBlurDesc& blur = scene.quality.motion_blur;
  const CacheInstants& cached = manifest_.instants;
  if (!blur.enabled() || (cached.per_frame == blur.samples && cached.shutter == blur.shutter)) {
    return std::nullopt;
  }
  const std::string held = cached.per_frame == 0
                               ? "holds no instants between frames"
                               : fmt::format("holds {} instants a frame over a shutter of {:g}",
                                             cached.per_frame, cached.shutter);
  return fmt::format(
      "the scene asks for motion blur of {} instants over a shutter of {:g}, and the cache {} {}, "
      "so its frames are drawn without motion blur; for the blur, simulate again with this scene "
      "(dinam simulate {} -o {}), which keeps the instants it asks for",
      blur.samples, blur.shutter, folder_.string(), held, scene.source.string(), folder_.string());
}

void MotionCache::check_model(const Model& model) const {
  bool same = model.objects.size() == manifest_.objects.size();
  for (std::size_t o = 0; same && o < model.objects.size(); ++o) {
    const CacheObjectEntry& cached = manifest_.objects[o];
    const ModelObject& object = model.objects[o];
    same = cached.name == object.name && cached.first_node == object.first_node &&
           cached.node_count == object.node_count && cached.bar_count == object.bar_count;
  }
  if (!same) {
    throw UserError(FileLoc{(folder_ / "manifest.json").string()},
                    "the cache's objects do not match the scene's model node for node; simulate "
                    "again");
  }
}

std::vector<std::vector<Vec3f>> MotionCache::read_frames(int first, int last) const {
  DINAM_CHECK(first >= 1 && first <= last && last <= manifest_.frame_count);
  std::vector<std::vector<Vec3f>> frames(static_cast<std::size_t>(last - first + 1),
                                         std::vector<Vec3f>(manifest_.node_count));
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const ObjectCache& cache = objects_[o];
    RegularFileIn in(cache.path, "the cache's point cache");
    for (int frame = first; frame <= last; ++frame) {
      std::vector<Vec3f>& positions = frames[static_cast<std::size_t>(frame - first)];
      read_point_cache_sample(in, cache.path, cache.header, frame - 1,
                              positions.data() + manifest_.objects[o].first_node);
    }
  }
  return frames;
}

std::vector<std::vector<Vec3f>> MotionCache::read_instants(int first, int last) const {
  DINAM_CHECK(manifest_.instants.per_frame > 0 && first >= 1 && first <= last &&
              last <= manifest_.frame_count);
  const int per_frame = manifest_.instants.per_frame;
  std::vector<std::vector<Vec3f>> instants(static_cast<std::size_t>((last - first + 1) * per_frame),
                                           std::vector<Vec3f>(manifest_.node_count));
  RegularFileIn in(instants_.path, "the cache's motion blur instants");
  for (std::size_t i = 0; i < instants.size(); ++i) {
    read_point_cache_sample(in, instants_.path, instants_.header,
                            (first - 1) * per_frame + static_cast<std::int32_t>(i),
                            instants[i].data());
  }
  return instants;
}

}  // namespace dinam
