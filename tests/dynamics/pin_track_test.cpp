// Pins that follow a point cache (`pin_motion: {point_cache: …}`, scene/pin_track_reader.hpp,
// dynamics/pin_motion.hpp): an animated collider or a hand carrying a cloth, as an animation
// package exports it. The pinned nodes must be exactly where the cache puts them, placed as the
// mesh is, under either integrator; a cache that is not of the mesh is refused at its key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/pin_motion.hpp"
#include "io/point_cache.hpp"
#include "model/model.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A square of wire, four vertices in the file's order, lying in the file's x–y plane.
constexpr const char* kSquareObj =
    "v 0 0 0\nv 0.5 0 0\nv 0.5 0.5 0\nv 0 0.5 0\nl 1 2\nl 2 3\nl 3 4\nl 4 1\nl 1 3\n";

// The square's vertex v at sample s of the test's track, in the file's coordinates: it slides
// along x and rises along the file's y, turning a little (each vertex its own path), float32 as a
// PC2 holds it.
Vec3f sample_point(int s, int v) {
  static const std::array<Vec3f, 4> rest = {Vec3f(0, 0, 0), Vec3f(0.5f, 0, 0), Vec3f(0.5f, 0.5f, 0),
                                            Vec3f(0, 0.5f, 0)};
  const float turn = 0.05f * static_cast<float>(s);
  const Vec3f p = rest[static_cast<std::size_t>(v)];
  return {p.x() - turn * p.y() + 0.02f * static_cast<float>(s),
          p.y() + turn * p.x() + 0.01f * static_cast<float>(s), p.z()};
}

void write_track(const std::filesystem::path& path, int samples, int points = 4,
                 float frames_per_sample = 1.0f) {
  PointCacheHeader header;
  header.format = PointCacheFormat::kPc2;
  header.point_count = points;
  header.sample_count = samples;
  header.start_frame = 1.0f;
  header.sample_rate = frames_per_sample;
  PointCacheWriter writer(path, header);
  for (int s = 0; s < samples; ++s) {
    std::vector<Vec3f> sample;
    for (int v = 0; v < points; ++v) {
      sample.push_back(sample_point(s, v % 4));
    }
    writer.add_sample(sample.data());
  }
  writer.close();
}

struct TrackScene {
  test::TemporaryFolder folder{"pin-track"};
  std::string obj = kSquareObj;  // the mesh file's text

  // A scene of the square, pinned whole and following `track.pc2`, placed with `placement`
  // (mesh keys), beside `rest` (more objects and keys).
  SceneDescription read(const std::string& placement, const std::string& motion,
                        const std::string& integrator = "central_difference") {
    std::ofstream(folder.path() / "square.obj") << obj;
    const std::string yaml = fmt::format(R"(version: 1
integrator: {}
duration: 1
fps: 20
ground: {{contact: false}}
objects:
  - name: hand
    mesh: {{file: square.obj{}}}
    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.005}}
    pinned: {{all: true}}
    pin_motion: {}
)",
                                         integrator, placement, motion);
    return read_scene_text(yaml, folder.path() / "scene.yaml");
  }
};

// The track placed as the mesh: turned by up_axis y (file y → world z), scaled, then moved.
Vec3 placed(const Vec3f& p) {
  return Vec3(2.0 * p.x(), -2.0 * p.z(), 2.0 * p.y()) + Vec3(0, 0, 1);
}

TEST(PinTrack, PinnedNodesAreWhereTheCachePutsThemUnderEitherIntegrator) {
  for (const std::string integrator : {"central_difference", "implicit"}) {
    SCOPED_TRACE(integrator);
    TrackScene scene;
    write_track(scene.folder.path() / "track.pc2", 11);
    const Model model = build_model(scene.read(", up_axis: y, scale: 2, translation: [0, 0, 1]",
                                               "{point_cache: track.pc2}", integrator));
    ASSERT_EQ(model.pin_motions.size(), 1u);
    const TimeStep timestep = choose_timestep(model, std::nullopt, 20.0, {});
    const std::unique_ptr<Stepper> stepper = stepper_kind(model).make_stepper(model, timestep);
    State state = stepper->start(false);
    // Each frame's time is a sample's, and between two the track is as far on as the time; after
    // the last sample (frame 11, t = 0.5 s) the pins hold still. Looked at every third of a
    // frame's steps (most instants between samples).
    const int steps = std::max(timestep.steps_per_frame / 3, 1);
    for (int k = 0; k <= 60; ++k) {
      const double at = state.time * 20.0;  // samples since t = 0
      for (int v = 0; v < 4; ++v) {
        const int s = std::min(static_cast<int>(std::floor(at)), 10);
        const double share = std::min(at, 10.0) - s;
        const Vec3 a = placed(sample_point(s, v));
        const Vec3 expected = share == 0.0 ? a : a + share * (placed(sample_point(s + 1, v)) - a);
        // 1e-12 m: the placement's and the position update's rounding (x_{n+1} = x_n + Δt v,
        // v the secant to the track), far below a sample's 1e-2 m move.
        EXPECT_LT((state.x[static_cast<std::size_t>(v)] - expected).norm(), 1e-12)
            << "vertex " << v << " at t = " << state.time;
      }
      stepper->advance(state, steps);
    }
  }
}

TEST(PinTrack, SamplesSomeFramesApartAreTimedByTheScenesFps) {
  TrackScene scene;
  // Two frames a sample: sample 3 is at frame 6, t = 0.3 s.
  write_track(scene.folder.path() / "track.pc2", 6, 4, 2.0f);
  const Model model = build_model(scene.read("", "{point_cache: track.pc2}"));
  const Vec3 at_sample_3 = model.pin_motions[0].track[3 * 4 + 2];
  EXPECT_EQ(driven_position(model, model.pin_motions[0], 2, 0.3), at_sample_3);
  EXPECT_DOUBLE_EQ(model.pin_motions[0].interval, 0.1);
  // Half-way to sample 4, and held at the last (sample 5, t = 0.5 s) after it.
  const Vec3 at_sample_4 = model.pin_motions[0].track[4 * 4 + 2];
  EXPECT_LT(
      (driven_position(model, model.pin_motions[0], 2, 0.35) - 0.5 * (at_sample_3 + at_sample_4))
          .norm(),
      1e-15);
  EXPECT_EQ(driven_position(model, model.pin_motions[0], 2, 0.9),
            model.pin_motions[0].track[5 * 4 + 2]);
}

// A cache far longer than the scene (100 000 samples, one a frame, for a scene of 20 frames) is
// read as far as the run reaches: sample 20 (t = 1 s, its last frame) and the next, not the rest,
// which a header can claim by the billion; the path within the run is the same.
TEST(PinTrack, ACacheLongerThanTheRunIsReadAsFarAsTheRunReaches) {
  TrackScene scene;
  write_track(scene.folder.path() / "track.pc2", 100000);
  const Model model = build_model(scene.read("", "{point_cache: track.pc2}"));
  ASSERT_EQ(model.pin_motions[0].track.size(), 22U * 4U);
  const SceneDescription read = scene.read("", "{point_cache: track.pc2}");
  EXPECT_EQ(read.objects[0].pin_motion.track.size(), 22U * read.objects[0].mesh.vertices.size());
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(driven_position(model, model.pin_motions[0], v, 1.0),
              sample_point(20, v).cast<double>())
        << v;
  }
}

TEST(PinTrack, ACacheThatIsNotOfTheMeshIsRefusedAtItsKey) {
  TrackScene scene;
  write_track(scene.folder.path() / "five.pc2", 3, 5);
  write_track(scene.folder.path() / "track.pc2", 3);
  std::ofstream(scene.folder.path() / "track.txt") << "not a cache";
  std::ofstream(scene.folder.path() / "broken.pc2") << "POINTCACHE2";
  const auto refused = [&](const std::string& motion, std::initializer_list<std::string> says) {
    test::expect_user_error([&] { scene.read("", motion); }, 11, says);
  };
  refused("{point_cache: five.pc2}", {"5 points a sample", "4 vertices", "same mesh"});
  refused("{point_cache: missing.pc2}", {"no file", "missing.pc2", "scene's folder"});
  refused("{point_cache: track.txt}", {".pc2", ".mdd", "track.txt"});
  refused("{point_cache: track.pc2, displacement: [0, 0, 1]}",
          {"whole path", "leave out 'displacement'"});
  // A broken file names the file itself, and what to do.
  test::expect_user_error([&] { scene.read("", "{point_cache: broken.pc2}"); }, 0,
                          {"broken.pc2", "export it again"});
}

// A cache exported again under the same name, its pins moving otherwise, is another motion: the
// scene's motion settings (what a motion cache is checked against) tell the two apart.
TEST(PinTrack, ACacheExportedAgainChangesTheMotionSettings) {
  TrackScene scene;
  write_track(scene.folder.path() / "track.pc2", 4);
  const SceneDescription first = scene.read("", "{point_cache: track.pc2}");
  EXPECT_EQ(scene.read("", "{point_cache: track.pc2}").motion_settings, first.motion_settings);
  write_track(scene.folder.path() / "track.pc2", 5);  // one more frame of the animation
  EXPECT_NE(scene.read("", "{point_cache: track.pc2}").motion_settings, first.motion_settings);
}

TEST(PinTrack, AFirstSampleAwayFromTheMeshIsWarnedOf) {
  TrackScene scene;
  write_track(scene.folder.path() / "track.pc2", 3);
  EXPECT_TRUE(scene.read("", "{point_cache: track.pc2}").warnings.empty());
  // The mesh written at another frame than the cache's first: the pins would jump 0.3 m at t = 0.
  scene.obj = "v 0.3 0 0\nv 0.8 0 0\nv 0.8 0.5 0\nv 0.3 0.5 0\nl 1 2\nl 2 3\nl 3 4\nl 4 1\n";
  const SceneDescription moved = scene.read("", "{point_cache: track.pc2}");
  ASSERT_EQ(moved.warnings.size(), 1u);
  EXPECT_NE(moved.warnings[0].find("jump"), std::string::npos) << moved.warnings[0];
  EXPECT_NE(moved.warnings[0].find("0.3 m"), std::string::npos) << moved.warnings[0];
}

}  // namespace
}  // namespace dinam
