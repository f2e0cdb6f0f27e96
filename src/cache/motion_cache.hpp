#pragma once
// Reads a motion cache that `dinam simulate` wrote (motion_cache_writer.hpp): checks that it is
// complete and that it holds the motion of the scene at hand, then reads any range of frames
// without simulating anything.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cache/manifest.hpp"
#include "io/point_cache.hpp"

namespace dinam {

struct Model;

class MotionCache {
 public:
  // Reads the manifest and checks every point cache it lists (header and length). Throws UserError
  // when the folder is not a complete cache.
  explicit MotionCache(std::filesystem::path folder);

  const CacheManifest& manifest() const { return manifest_; }
  const std::filesystem::path& folder() const { return folder_; }

  // Throws UserError when `scene` would not move as the cache does: made by another dinam
  // version, or from settings that differ (the message names them and says whether the cache came
  // from another scene file). Edits to the look only (camera, image, light, colours) pass.
  void check_scene(const SceneDescription& scene) const;

  // Throws UserError when the model's objects are not the cached ones, node for node.
  void check_model(const Model& model) const;

  // Where the scene asks for motion blur that the cache's instants do not give (none, another
  // count or another shutter): what the cache holds and how to make one that gives it; none where
  // they match. The camera, light and image never invalidate a cache: such frames are drawn
  // without blur (render_input.cpp).
  std::optional<std::string> motion_blur_shortfall(const SceneDescription& scene) const;

  // Every node's position in frames first … last (1-based, inclusive), as drawn.
  std::vector<std::vector<Vec3f>> read_frames(int first, int last) const;

  // Every node's position at each instant of frames first … last (frame after frame,
  // manifest().instants.per_frame each). The cache must hold instants.
  std::vector<std::vector<Vec3f>> read_instants(int first, int last) const;

 private:
  struct ObjectCache {
    std::filesystem::path path;
    PointCacheHeader header;
  };

  std::filesystem::path folder_;
  CacheManifest manifest_;
  std::vector<ObjectCache> objects_;  // the cache each object is read from: PC2, else MDD
  ObjectCache instants_;              // motion blur's, when the cache holds them
};

}  // namespace dinam
