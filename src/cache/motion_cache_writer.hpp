#pragma once
// Writes a motion cache: a folder with each object's rest mesh (OBJ), its point caches (PC2 and
// optionally MDD), optionally a USD stage of them all, and manifest.json. Everything goes into a
// temporary folder beside the final one
// ("DIR.part-HOST-PID"), and only a complete cache is moved to the final name, replacing an older
// cache there in one step; so a cache is complete or absent, and an interrupted run leaves no
// folder that looks like a cache.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cache/manifest.hpp"
#include "cache/usd_stage.hpp"
#include "io/point_cache.hpp"

namespace dinam {

struct Model;

struct CacheRequest {
  std::filesystem::path folder;  // the cache; an existing cache there is replaced on commit
  bool pc2 = true;
  bool mdd = false;
  double fps = 0.0;
  int frame_count = 0;  // samples in each point cache
  // Motion blur: each frame's instants as steps from its own step (frame_source.hpp), and the
  // shutter they came from; empty for none.
  std::vector<int> instant_offsets;
  double shutter = 0.0;
  int steps_per_frame = 1;
  bool usd = false;  // a USD stage of every object too (usd_stage.hpp)
  // (n_objects) how the scene draws each object, for the manifest and the USD stage; the radii
  // are given at commit. Empty: from the model (faces as surfaces, an object without as wires).
  std::vector<ObjectLook> looks;
};

class MotionCacheWriter {
 public:
  // Checks that `request.folder` is absent, empty or a cache (anything else is a UserError, so
  // that a mistyped -o never replaces someone's files), removes temporary folders that dead runs
  // of this machine left beside it, then writes the rest meshes into a new temporary folder.
  MotionCacheWriter(const CacheRequest& request, const Model& model);
  ~MotionCacheWriter();  // removes the temporary folder unless committed
  MotionCacheWriter(const MotionCacheWriter&) = delete;
  MotionCacheWriter& operator=(const MotionCacheWriter&) = delete;

  // Adds the next frame: every node's position, as drawn.
  void add_frame(const std::vector<Vec3f>& positions);

  // Adds the next instant of motion blur (frame after frame, instant_offsets.size() each).
  void add_instant(const std::vector<Vec3f>& positions);

  // Where a further file of the cache goes (energy.csv) until commit moves it with the rest.
  std::filesystem::path file_path(const std::string& name) const { return temporary_ / name; }

  // The boxes of the frames added so far.
  const std::vector<FrameBounds>& frame_bounds() const { return frame_bounds_; }

  // After the last frame: completes `manifest` with what the writer knows (version, objects and
  // their files, fps, frame count, bounds), writes it and the USD stage (its wires drawn with
  // `wire_radii`, one per object, m; empty: each object's wire radius), and moves the cache into
  // place.
  void commit(CacheManifest manifest, const std::vector<float>& wire_radii = {});

 private:
  // Writes each object's rest mesh and opens its point caches in the temporary folder.
  void open_files(const Model& model);
  // Removes the temporary folder and everything in it.
  void discard();

  struct ObjectFiles {
    Index first_node = 0;
    Index node_count = 0;
    std::vector<PointCacheWriter> caches;
  };

  CacheRequest request_;
  std::filesystem::path temporary_;
  std::vector<CacheObjectEntry> entries_;
  std::vector<ObjectFiles> files_;
  std::vector<FrameBounds> frame_bounds_;
  std::unique_ptr<PointCacheWriter> instants_;  // null without motion blur
  std::unique_ptr<UsdStageWriter> usd_;         // null without USD
  Index node_count_ = 0;
  bool committed_ = false;
};

// A file name for an object's files from its name: letters, digits, '-', '_' and '.' kept, any
// other character made '_', never empty or hidden, and at most kLongestCacheStem bytes.
inline constexpr std::size_t kLongestCacheStem = 100;
std::string cache_file_stem(const std::string& object_name);

}  // namespace dinam
