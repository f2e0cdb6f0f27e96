// The pipeline without OpenGL: a recording Renderer shows what would be drawn, from which camera.
#include "run/frame_source.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/thread_governor.hpp"
#include "core/thread_team.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "render/camera.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/frame_drawing.hpp"

namespace dinam {
namespace {

class RecordingRenderer final : public Renderer {
 public:
  struct Call {
    std::vector<Vec3f> positions;
    RenderCamera camera;
  };
  using Renderer::render;
  void render(const DrawList& list, std::span<const FrameSample> samples, Image& image) override {
    calls.push_back({*samples[0].positions, samples[0].camera});
    lists.push_back(&list);
    image = Image(4, 4);
  }
  std::vector<Call> calls;
  std::vector<const DrawList*> lists;
};

// A swinging cloth and a pinned pole: 12 frames.
std::string scene_text(const std::string& camera) {
  return R"(version: 1
duration: 0.6
fps: 20
image: {width: 320, height: 180}
)" + camera +
         R"(
objects:
  - name: pole
    mesh: {polyline: {points: [[0, 0, 0], [0, 0, 2]], segments: 2}}
    material: {density: 7800, youngs_modulus: 2e11, radius: 0.02}
    pinned: {all: true}
  - name: cloth
    mesh: {grid: {width: 1, height: 0.6, columns: 4, rows: 3, diagonals: none}, rotation: [90, 0, 0], translation: [0, 0, 1.4]}
    material: {density: 1200, youngs_modulus: 2e7, radius: 0.001}
    pinned: {box: {min: [-0.01, -0.01, 1.39], max: [0.01, 0.01, 2.01]}}
)";
}

struct Pipeline {
  SceneDescription scene;
  Model model;
  SimulatedFrames frames;
  FrameCameras cameras;
};

// Simulates the scene and decides its cameras.
Pipeline run_scene(const std::string& text) {
  Pipeline p{test::scene_from_yaml(text), {}, {}, {}};
  p.model = build_model(p.scene);
  const TimeStep timestep = choose_timestep(p.model, std::nullopt, p.scene.fps, {});
  p.frames = simulate_frames(p.model, timestep, p.scene.frame_count(), false);
  p.cameras = frame_cameras(p.scene, p.model, p.frames);
  return p;
}

Pipeline run_pipeline(const std::string& camera) {
  return run_scene(scene_text(camera));
}

// A run whose thread count follows the machine (core/thread_governor.hpp) draws the frames of a
// run on one thread, bit for bit, however often the count changes: here a made-up load that
// comes and goes every other run of steps moves a cloth large enough to share between 1, 2 and 3.
TEST(FrameSource, AThreadCountThatFollowsTheLoadLeavesEveryFrameTheSame) {
  const std::string scene = R"(version: 1
duration: 0.06
fps: 100
wind: {velocity: [3, 0, 0], turbulence: {amplitude: 1, scale: 0.3}}
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 60, rows: 60, diagonals: one}, rotation: [90, 0, 0], translation: [0, 0, 1.2]}
    material: {density: 1200, youngs_modulus: 2e7, radius: 0.001, breaking: {force: 0.5}}
    pinned: {box: {min: [-0.01, -1, 0], max: [0.01, 1, 2]}}
)";
  const Model model = build_model(test::scene_from_yaml(scene));
  ASSERT_GE(model.bar_count() + model.bend_count(), kMinParallelItems);
  const TimeStep timestep = choose_timestep(model, std::nullopt, 100, {});
  set_thread_policy({1, 1, false, 1, "--threads 1"});
  const SimulatedFrames one = simulate_frames(model, timestep, 7, false);

  std::vector<int> counts_run;
  int reading = 0;
  set_thread_policy(
      {2, 3, true, 3, "own choice"},
      [&] {
        counts_run.push_back(thread_count());
        return std::optional<double>(reading++ / 2 % 2 == 0 ? 2.0 : 0.0);
      },
      0.0);
  const SimulatedFrames following = simulate_frames(model, timestep, 7, false);
  set_thread_policy({1, 1, false, 1, "--threads 1"});

  // It did change: every count was run, the ones a load of 2 or of 0 on 3 CPUs leaves room for.
  for (const int count : {1, 2, 3}) {
    EXPECT_NE(std::count(counts_run.begin(), counts_run.end(), count), 0) << count;
  }
  ASSERT_EQ(following.positions.size(), one.positions.size());
  for (std::size_t f = 0; f < one.positions.size(); ++f) {
    EXPECT_TRUE(one.positions[f] == following.positions[f]) << "frame " << f + 1;
  }
  EXPECT_EQ(following.tears.size(), one.tears.size());
}

TEST(FrameSource, DrawsEachChosenFrameOnceWithItsPositions) {
  const Pipeline p = run_pipeline("camera: auto");
  const DrawList list = make_draw_list(p.scene, p.model, motion_bounds(p.frames.positions));
  RecordingRenderer renderer;
  std::vector<int> written;
  draw_frames(renderer, list, p.frames, p.cameras, 3, 7,
              [&](int frame, const Image&) { written.push_back(frame); });
  EXPECT_EQ(written, (std::vector<int>{3, 4, 5, 6, 7}));
  ASSERT_EQ(renderer.calls.size(), 5u);
  EXPECT_EQ(renderer.calls[0].positions, p.frames.positions[2]);
  EXPECT_NE(renderer.calls[4].positions, renderer.calls[0].positions);  // the cloth moved
}

// A tear shown from frame 5: the frames before draw the whole cloth; from frame 5 on, the torn
// bar's triangles (it is an edge of two) are collapsed, and the list's revision tells the
// renderer to upload its surfaces again.
TEST(FrameSource, TornBarsLeaveTheDrawingFromTheirFrame) {
  Pipeline p = run_pipeline("camera: auto");
  // Bars tear only in a scene whose material can break, which is drawn as simulated; this one's
  // tear is made up, so its surface is asked to be drawn so too.
  p.scene.objects[1].subdivide = 0;
  const DrawList list = make_draw_list(p.scene, p.model, motion_bounds(p.frames.positions));
  Index torn = -1;  // a cloth bar inside the grid: an edge of two faces
  for (Index b = 0; b < p.model.bar_count() && torn < 0; ++b) {
    const Vec3& a = p.model.node_initial_x[p.model.bar_nodes[2 * b]];
    const Vec3& c = p.model.node_initial_x[p.model.bar_nodes[2 * b + 1]];
    torn = p.model.bar_on_face[b] != 0 && a.z() == c.z() && a.z() > 1.5 && a.z() < 1.9 ? b : -1;
  }
  ASSERT_GE(torn, 0);
  p.frames.tears.push_back({5, p.model.bar_nodes[2 * torn], p.model.bar_nodes[2 * torn + 1]});
  struct CountingRenderer : Renderer {
    using Renderer::render;
    void render(const DrawList& drawn, std::span<const FrameSample>, Image& image) override {
      int collapsed = 0;
      for (const SurfaceBatch& batch : drawn.surfaces) {
        for (std::size_t k = 0; k + 2 < batch.triangles.size(); k += 3) {
          collapsed += batch.triangles[k] == batch.triangles[k + 1] ? 1 : 0;
        }
      }
      collapsed_per_frame.push_back(collapsed);
      revisions.push_back(drawn.revision);
      image = Image(4, 4);
    }
    std::vector<int> collapsed_per_frame;
    std::vector<std::uint64_t> revisions;
  } renderer;
  draw_frames(renderer, list, p.frames, p.cameras, 3, 7, [](int, const Image&) {});
  EXPECT_EQ(renderer.collapsed_per_frame, (std::vector<int>{0, 0, 2, 2, 2}));
  EXPECT_LT(renderer.revisions[1], renderer.revisions[2]);
  EXPECT_EQ(renderer.revisions[2], renderer.revisions[3]);  // nothing newly torn: drawn as it was
  // Drawn again, the torn copy is made afresh at the same place: a new revision all the same, so
  // a renderer never takes it for the last call's copy with its tears.
  const std::uint64_t before = renderer.revisions.back();
  draw_frames(renderer, list, p.frames, p.cameras, 5, 5, [](int, const Image&) {});
  EXPECT_NE(renderer.revisions.back(), before);
}

TEST(FrameSource, AutoCameraKeepsStillAndSeesEveryPointOfEveryFrame) {
  const Pipeline p = run_pipeline("camera: auto");
  for (const RenderCamera& camera : p.cameras.frames) {
    EXPECT_EQ(camera.position, p.cameras.frames.front().position);  // the view does not jump
  }
  for (const auto& positions : p.frames.positions) {
    for (const Vec3f& x : positions) {
      const Eigen::Vector2f pixel = pixel_from_world(p.cameras.frames.front(), 320, 180, x);
      EXPECT_GE(pixel.x(), 0.0f);
      EXPECT_LE(pixel.x(), 320.0f);
      EXPECT_GE(pixel.y(), 0.0f);
      EXPECT_LE(pixel.y(), 180.0f);
    }
  }
}

// A 16 × 16 plate of 1 m dropped tilted from 0.3 m onto the ground, and (with `fragment`) a short
// wire 20 m away: 2 of its 291 nodes, the kind of stray piece a downloaded file carries.
Pipeline dropped_plate(bool fragment) {
  std::string text = R"(version: 1
duration: 1.0
fps: 10
image: {width: 320, height: 180}
objects:
  - name: plate
    mesh: {grid: {width: 2, height: 2, columns: 16, rows: 16}, fit: {size: 1}, rotation: [30, 0, 0],
           translation: [0, 0, 0.3]}
    material: {density: 1100, youngs_modulus: 5.0e7, radius: 0.004}
)";
  if (fragment) {
    text += R"(  - name: fragment
    mesh: {polyline: {points: [[20, 0, 1], [20.05, 0, 1]]}}
    material: {density: 1100, youngs_modulus: 5.0e7, radius: 0.004}
)";
  }
  return run_scene(text);
}

TEST(FrameSource, AutoCameraFramesADroppedModelTightlyIgnoringAFarFragment) {
  for (const bool fragment : {false, true}) {
    SCOPED_TRACE(fragment ? "with a fragment 20 m away" : "alone");
    const Pipeline p = dropped_plate(fragment);
    const ModelObject& plate = p.model.objects[0];
    const int width = p.scene.image_width;
    const int height = p.scene.image_height;
    double smallest_span = 1.0;
    for (std::size_t f = 0; f < p.frames.positions.size(); ++f) {
      Eigen::Vector2f lo = Eigen::Vector2f::Constant(1e30f);
      Eigen::Vector2f hi = -lo;
      for (Index i = plate.first_node; i < plate.first_node + plate.node_count; ++i) {
        const Eigen::Vector2f pixel =
            pixel_from_world(p.cameras.frames[f], width, height, p.frames.positions[f][i]);
        lo = lo.cwiseMin(pixel);
        hi = hi.cwiseMax(pixel);
      }
      // All of the plate is in the picture, and it spans half its width or height at least.
      EXPECT_GE(lo.minCoeff(), 0.0f) << "frame " << f + 1;
      EXPECT_LE(hi.x(), static_cast<float>(width)) << "frame " << f + 1;
      EXPECT_LE(hi.y(), static_cast<float>(height)) << "frame " << f + 1;
      const double span = std::max(static_cast<double>(hi.x() - lo.x()) / width,
                                   static_cast<double>(hi.y() - lo.y()) / height);
      smallest_span = std::min(smallest_span, span);
    }
    EXPECT_GE(smallest_span, 0.5);
    testing::Test::RecordProperty(fragment ? "smallest_span_with_fragment" : "smallest_span",
                                  fmt::format("{:.3f}", smallest_span));
  }
}

TEST(FrameSource, FollowCameraKeepsItsOffsetFromTheObject) {
  const Pipeline p = run_pipeline("camera: {follow: cloth, offset: [2, -3, 1]}");
  for (std::size_t k = 0; k < p.cameras.frames.size(); ++k) {
    Vec3f centroid = Vec3f::Zero();
    const ModelObject& cloth = p.model.objects[1];
    for (Index i = 0; i < cloth.node_count; ++i) {
      centroid += p.frames.positions[k][cloth.first_node + i];
    }
    centroid /= static_cast<float>(cloth.node_count);
    EXPECT_TRUE(p.cameras.frames[k].look_at.isApprox(centroid, 1e-5f));
    EXPECT_TRUE((p.cameras.frames[k].position - p.cameras.frames[k].look_at)
                    .isApprox(Vec3f(2, -3, 1), 1e-5f));
  }
}

// A fine wire is drawn at least 0.2 % of the scene's size across, so that it shows; but the bars of
// a dense mesh no thicker than a quarter of its median bar, so that they stay apart.
TEST(DrawListFromModel, DrawnWiresAreVisibleYetADenseMeshStaysAMesh) {
  const auto radius_of = [](int cells) {
    const SceneDescription scene = test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - name: net
    mesh: {{grid: {{width: 1, height: 1, columns: {0}, rows: {0}, diagonals: none}}}}
    material: {{density: 1000, youngs_modulus: 1.0e6, radius: 0.0001}}
    style: wire
)",
                                                                     cells));
    const Model model = build_model(scene);
    Bounds bounds;
    for (const Vec3& p : model.node_initial_x) {
      bounds.add(p.cast<float>());
    }
    const DrawList list = make_draw_list(scene, model, bounds);
    return static_cast<double>(list.segment_radius.front());
  };
  // The scene is about 1.4 m across: at least 0.2 % of it, 2.8 mm, for 0.25 m bars...
  const double extent = 2.0 * std::sqrt(0.5);
  EXPECT_NEAR(radius_of(4), 0.002 * extent, 1e-4);
  // ... but at most a quarter of 1 cm bars, 2.5 mm, and the wire's own 0.1 mm is less.
  EXPECT_NEAR(radius_of(100), 0.0025, 1e-6);
}

TEST(DrawListFromModel, SurfacesReplaceBarsForClothAndColoursFollowObjects) {
  const Pipeline p = run_pipeline("camera: auto");
  const DrawList list = make_draw_list(p.scene, p.model, motion_bounds(p.frames.positions));
  // The pole is drawn as wires (2 bars); the cloth (12 quads) as one surface of 24 triangles,
  // smoothed by default to level 2 (16 each: 384 still under the default's 2 000).
  EXPECT_EQ(list.segment_radius.size(), 2u);
  ASSERT_EQ(list.surfaces.size(), 1u);
  EXPECT_EQ(list.surfaces[0].triangles.size(), 16u * 24u * 3u);
  EXPECT_EQ(list.surfaces[0].texture, -1);
  // The shadow map's box holds every point of every frame.
  const Bounds motion = motion_bounds(p.frames.positions);
  EXPECT_TRUE((list.shadow_bounds_min.array() <= motion.min.array()).all());
  EXPECT_TRUE((list.shadow_bounds_max.array() >= motion.max.array()).all());
}

}  // namespace
}  // namespace dinam
