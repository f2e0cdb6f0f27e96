// The motion cache: what is written reads back bit for bit, a cache is complete or absent, and a
// cache is refused for a scene whose motion would differ.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "cache/motion_cache.hpp"
#include "cache/motion_cache_writer.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "run/frame_source.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A rope held at one end that swings down: 4 frames at 10 fps.
const char* const kRope = R"(version: 1
name: rope
duration: 0.4
fps: 10
camera: {position: [0.5, -3, 1], look_at: [0.5, 0, 0.8]}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 8}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    pinned: {indices: [0]}
    color: [0.1, 0.9, 0.1]
)";

using test::replaced;

struct Simulated {
  SceneDescription scene;
  Model model;
  SimulatedFrames frames;
};

Simulated simulate(const std::string& yaml) {
  Simulated s{test::scene_from_yaml(yaml), {}, {}};
  s.model = build_model(s.scene);
  const TimeStep timestep = choose_timestep(s.model, s.scene.timestep, s.scene.fps, {});
  s.frames = simulate_frames(s.model, timestep, s.scene.frame_count(), false);
  return s;
}

CacheRequest request_for(const Simulated& s, const std::filesystem::path& folder) {
  return {folder, true, true, s.scene.fps, s.scene.frame_count(), {}, 0.0, 1, false, {}};
}

// Writes the whole cache of `s` into `folder`, its objects drawn as `looks` says (empty: as the
// model's own look).
void write_cache(const Simulated& s, const std::filesystem::path& folder,
                 std::vector<ObjectLook> looks = {}) {
  CacheRequest request = request_for(s, folder);
  request.looks = std::move(looks);
  MotionCacheWriter writer(request, s.model);
  for (const auto& positions : s.frames.positions) {
    writer.add_frame(positions);
  }
  CacheManifest manifest;
  manifest.scene_path = canonical_scene_path(s.scene.source);
  manifest.scene_name = s.scene.name;
  manifest.motion_settings = s.scene.motion_settings;
  for (const TornBar& tear : s.frames.tears) {
    manifest.tears.push_back({tear.frame, tear.n0, tear.n1});
  }
  writer.commit(manifest);
}

TEST(MotionCache, FramesReadBackBitForBitWithTheBoundsOfTheWholeMotion) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("cache");
  write_cache(s, folder.path() / "cache");
  const MotionCache cache(folder.path() / "cache");
  EXPECT_EQ(cache.manifest().frame_count, 4);
  EXPECT_EQ(cache.manifest().node_count, s.model.node_count());
  EXPECT_EQ(test::folder_entries(folder.path() / "cache"),
            (std::vector<std::string>{"manifest.json", "rope.mdd", "rope.obj", "rope.pc2"}));
  const auto frames = cache.read_frames(2, 4);
  ASSERT_EQ(frames.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(frames[k], s.frames.positions[k + 1]) << "frame " << k + 2;
  }
  const SimulatedFrames chunk = cached_frames(cache, 3, 3);
  EXPECT_EQ(chunk.at(3), s.frames.positions[2]);
  EXPECT_EQ(chunk.motion.min, s.frames.motion.min);  // all four frames, not only frame 3
  EXPECT_EQ(chunk.motion.max, s.frames.motion.max);
}

// An object from an OBJ file maps its points to the file's vertices in the manifest where they
// are not the file's vertices one for one (out_of_order.obj drops vertex 4 and welds vertex 5),
// and says nothing where they are (rope.obj) or where there is no file (a polyline).
TEST(MotionCache, TheManifestMapsPointsToTheMeshFilesVertices) {
  const Simulated s = simulate(R"(version: 1
duration: 0.2
fps: 10
objects:
  - name: square
    mesh: {file: out_of_order.obj}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    pinned: {all: true}
  - name: rope
    mesh: {file: rope.obj, translation: [0, 0, 1]}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    pinned: {all: true}
  - name: line
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]]}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    pinned: {all: true}
)");
  const test::TemporaryFolder folder("cache");
  write_cache(s, folder.path() / "cache");
  const CacheManifest manifest = MotionCache(folder.path() / "cache").manifest();
  ASSERT_EQ(manifest.objects.size(), 3u);
  EXPECT_EQ(manifest.objects[0].source_vertex_count, 6);
  EXPECT_EQ(manifest.objects[0].source_vertices, (std::vector<Index>{0, 1, 2, 3}));
  EXPECT_EQ(manifest.objects[1].source_vertex_count, 5);
  EXPECT_TRUE(manifest.objects[1].source_vertices.empty());
  EXPECT_EQ(manifest.objects[2].source_vertex_count, 0);
  EXPECT_TRUE(manifest.objects[2].source_vertices.empty());
}

// A rope that tears: its tears travel in the manifest, so frames drawn from the cache (in any
// chunk) lose the same bars from the same frames as the simulation's.
TEST(MotionCache, TearsReadBackWithTheFrames) {
  Simulated s = simulate(
      replaced(replaced(kRope, "radius: 0.004}", "radius: 0.004, breaking: {strain: 0.001}}"),
               "duration: 0.4", "duration: 0.4\nforces: [{acceleration: [0, 0, -200]}]"));
  ASSERT_FALSE(s.frames.tears.empty());
  const test::TemporaryFolder folder("cache");
  write_cache(s, folder.path() / "cache");
  const SimulatedFrames chunk = cached_frames(MotionCache(folder.path() / "cache"), 3, 4);
  ASSERT_EQ(chunk.tears.size(), s.frames.tears.size());
  for (std::size_t k = 0; k < chunk.tears.size(); ++k) {
    EXPECT_EQ(chunk.tears[k].frame, s.frames.tears[k].frame);
    EXPECT_EQ(chunk.tears[k].n0, s.frames.tears[k].n0);
    EXPECT_EQ(chunk.tears[k].n1, s.frames.tears[k].n1);
  }
}

TEST(MotionCache, AnAbandonedWriterLeavesNothingAndTheOldCacheStands) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("atomic");
  const auto path = folder.path() / "cache";
  {
    MotionCacheWriter writer(request_for(s, path), s.model);
    writer.add_frame(s.frames.positions[0]);
    EXPECT_EQ(test::folder_entries(folder.path()).size(), 1u);  // its temporary folder
  }  // destroyed before commit: an error or an interruption
  EXPECT_TRUE(test::folder_entries(folder.path()).empty());

  write_cache(s, path);
  const std::string created = MotionCache(path).manifest().created;
  {
    MotionCacheWriter writer(request_for(s, path), s.model);
    writer.add_frame(s.frames.positions[0]);
  }
  EXPECT_EQ(test::folder_entries(folder.path()), std::vector<std::string>{"cache"});
  EXPECT_EQ(MotionCache(path).manifest().created, created);

  // A complete new cache replaces the old one whole: a two-object scene in place of the rope.
  const Simulated two = simulate(replaced(kRope, "objects:\n", R"(objects:
  - name: post
    mesh: {polyline: {points: [[2, 0, 0], [2, 0, 1]]}}
    material: {density: 1000, youngs_modulus: 1.0e9, radius: 0.01}
    pinned: {all: true}
)"));
  write_cache(two, path);
  EXPECT_EQ(MotionCache(path).manifest().objects.size(), 2u);
  EXPECT_EQ(test::folder_entries(folder.path()), std::vector<std::string>{"cache"});
}

TEST(MotionCache, AFolderThatIsNotACacheIsNeverReplaced) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("notacache");
  std::ofstream(folder.path() / "thesis.tex") << "years of work";
  test::expect_user_error([&] { MotionCacheWriter(request_for(s, folder.path()), s.model); }, 0,
                          {"is not a motion cache", "choose another -o folder"});
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "thesis.tex"));
}

TEST(MotionCache, TemporaryFoldersOfDeadRunsAreRemoved) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("stale");
  const pid_t child = fork();  // a process id that no longer runs
  if (child == 0) {
    _exit(0);
  }
  waitpid(child, nullptr, 0);
  char host[256] = {};
  gethostname(host, sizeof(host) - 1);
  const std::string stale = "cache.part-" + cache_file_stem(host) + "-" + std::to_string(child);
  std::filesystem::create_directory(folder.path() / stale);
  std::filesystem::create_directory(folder.path() / "cache.part-otherhost-1");  // not ours to judge
  write_cache(s, folder.path() / "cache");
  EXPECT_EQ(test::folder_entries(folder.path()),
            (std::vector<std::string>{"cache", "cache.part-otherhost-1"}));
}

TEST(MotionCache, EditsToTheLookKeepTheCacheAndEditsToTheMotionAreRefusedByName) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("stale");
  write_cache(s, folder.path() / "cache");
  const MotionCache cache(folder.path() / "cache");

  const std::string look = replaced(replaced(kRope, "color: [0.1, 0.9, 0.1]", "color: [1, 0, 0]"),
                                    "look_at: [0.5, 0, 0.8]", "look_at: [0, 0, 0]");
  EXPECT_NO_THROW(cache.check_scene(test::scene_from_yaml(look)));

  const std::string heavier = replaced(kRope, "density: 1000", "density: 2000");
  test::expect_user_error(
      [&] { cache.check_scene(test::scene_from_yaml(heavier)); }, 0,
      {"the scene has changed since the cache",
       "objects[0].material.density: 1000 in the cache, 2000 now", "dinam simulate"});

  const SceneDescription other =
      read_scene_text(replaced(kRope, "duration: 0.4", "duration: 0.3"), "/elsewhere/other.yaml");
  test::expect_user_error([&] { cache.check_scene(other); }, 0,
                          {"was made from another scene", "duration: 0.4 in the cache, 0.3 now"});
}

TEST(MotionCache, ACacheOfAnotherVersionOrAnIncompleteOneIsRefused) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("version");
  const auto path = folder.path() / "cache";
  write_cache(s, path);
  std::stringstream text;
  text << std::ifstream(path / "manifest.json").rdbuf();
  std::ofstream(path / "manifest.json")
      << replaced(text.str(), "\"dinam_version\": \"", "\"dinam_version\": \"0.0.0-old");
  test::expect_user_error([&] { MotionCache(path).check_scene(s.scene); }, 0,
                          {"was made by dinam 0.0.0-old", "simulate again"});

  std::filesystem::remove(path / "manifest.json");
  test::expect_user_error([&] { MotionCache{path}; }, 0, {"not a complete motion cache"});
  test::expect_user_error([&] { MotionCache{folder.path() / "absent"}; }, 0,
                          {"no such folder", "dinam simulate"});
}

// How a surface is shaded travels in the manifest for `dinam view`: written only where it is not
// smooth (a cache made before `shading` reads as smooth), and a value dinam does not write is
// refused by name.
TEST(MotionCache, TheManifestKeepsHowASurfaceIsShaded) {
  const Simulated s = simulate(kRope);
  const test::TemporaryFolder folder("shading");
  const auto path = folder.path() / "cache";
  ObjectLook look;
  look.shading = Shading::kAuto;
  look.sharp_angle = 40.0;
  write_cache(s, path, {look});
  EXPECT_EQ(MotionCache(path).manifest().objects[0].look.shading, Shading::kAuto);
  EXPECT_EQ(MotionCache(path).manifest().objects[0].look.sharp_angle, 40.0);

  std::stringstream text;
  text << std::ifstream(path / "manifest.json").rdbuf();
  std::ofstream(path / "manifest.json")
      << replaced(text.str(), "\"shading\": \"auto\"", "\"shading\": \"bumpy\"");
  test::expect_user_error([&] { MotionCache{path}; }, 0,
                          {"shading 'bumpy'", "smooth, flat or auto", "simulate again"});
  // As a cache made before `shading` holds it: no such keys.
  std::ofstream(path / "manifest.json") << std::regex_replace(
      text.str(), std::regex(R"(,\s*"shading": "auto",\s*"sharp_angle": 40\.0)"), "");
  EXPECT_EQ(MotionCache(path).manifest().objects[0].look.shading, Shading::kSmooth);
}

}  // namespace
}  // namespace dinam
