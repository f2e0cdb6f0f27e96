#pragma once
// What the renderer draws, in its own terms: segments between points, spheres at points, surfaces
// over points, a ground and a light. render/ never sees springs or materials; app/ fills this from
// the model once, and each frame only the point positions (and the camera) change.
#include <atomic>
#include <cstdint>
#include <vector>

#include "core/image.hpp"
#include "core/look.hpp"
#include "core/types.hpp"

namespace dinam {

// A number no draw list's contents have had before in this process. A renderer keeps what it
// uploaded of a list by this number alone, so two lists never pass for one: copies made in turn
// at one address (a tear's, a snapshot probe's) each get their own.
inline std::uint64_t new_draw_list_revision() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

struct RenderCamera {
  Vec3f position{4.0f, -6.0f, 3.0f};
  Vec3f look_at{0.0f, 0.0f, 1.0f};
  Vec3f up{0.0f, 0.0f, 1.0f};
  float fov_degrees = 40.0f;  // vertical
};

// Points made from the frame's points, each frame: point k of these is Σ weights[j] × x[sources[j]]
// over j in [offsets[k], offsets[k + 1]) (a coarse mesh's subdivided surface,
// visual/surface_subdivision.hpp).
struct DerivedPoints {
  std::vector<Index> offsets{0};  // (n_points + 1)
  std::vector<Index> sources;
  std::vector<float> weights;

  Index size() const { return static_cast<Index>(offsets.size()) - 1; }
};

// Triangles drawn as one lit, two-sided surface, with one texture or the points' colours.
struct SurfaceBatch {
  std::vector<Index> triangles;  // (n_triangles × 3) point ids
  int texture = -1;              // index into DrawList::textures; −1 for the points' colours
};

struct DrawList {
  // The points a frame gives (its positions, n_given) are followed by these, made from them; the
  // per-point arrays below cover both (n_points = n_given + derived.size()).
  DerivedPoints derived;
  std::vector<Index> segment_points;  // (n_segments × 2) ids into the per-frame positions
  // (n_segments) m; a segment is a capsule, its round ends joining it to the segments that meet
  // it; a negative radius gives it flat ends instead.
  std::vector<float> segment_radius;
  std::vector<Vec3f> segment_color;       // (n_segments) linear RGB
  std::vector<Finish> segment_finish;     // (n_segments), or empty for the default finish
  std::vector<float> point_radius;        // (n_points) m; 0 draws no joint sphere
  std::vector<Vec3f> point_color;         // (n_points) linear RGB, also the surfaces' colour
  std::vector<Finish> point_finish;       // (n_points) of joints and surfaces, or empty
  std::vector<Eigen::Vector2f> point_uv;  // (n_points) texture coordinates of surface points
  std::vector<SurfaceBatch> surfaces;
  std::vector<Image> textures;  // sRGB-encoded RGBA, as read from PNG files
  // Its contents' number: a new one (new_draw_list_revision) whenever the points' colours, the
  // surfaces or the textures change after the list was made (a tear hides triangles), so that a
  // renderer uploads them again. A copy shares it while its contents are the same.
  std::uint64_t revision = new_draw_list_revision();

  bool ground_visible = true;
  bool ground_checker = true;            // a checkerboard, else one plain colour
  Vec3f ground_center = Vec3f::Zero();   // m, a point of the ground plane under the scene
  Vec3f ground_normal = Vec3f::UnitZ();  // unit
  float ground_half_size = 10.0f;  // m; the checker fades out towards this distance from the eye
  float ground_tile = 0.5f;        // m, checker size
  // A cyclorama around ground_center: the floor curves up, along a quarter circle of
  // `backdrop_curve` from `backdrop_radius` out, into a wall `backdrop_height` high, in the
  // ground's colour (render/backdrop_mesh.hpp). None while the radius is 0.
  float backdrop_radius = 0.0f;  // m
  float backdrop_curve = 0.0f;   // m
  float backdrop_height = 0.0f;  // m
  // Linear RGB: the ground's colour (a plain ground's, the checker's lighter squares) and the
  // checker's other squares; the sky's at the horizon and at the top of the picture.
  Vec3f ground_color{0.60f, 0.58f, 0.54f};
  Vec3f ground_checker_color{0.50f, 0.48f, 0.45f};
  Vec3f sky_horizon{0.78f, 0.82f, 0.86f};
  Vec3f sky_zenith{0.30f, 0.45f, 0.68f};

  Vec3f light_direction{0.35f, -0.45f, 0.82f};  // towards the light; normalised when drawn
  bool shadows = true;
  float light_size_degrees = 2.0f;  // the sun's apparent diameter, which sets soft penumbras
  // m: how far ambient occlusion looks for nearby surfaces; a few wire radii to a tenth of the
  // subject.
  float occlusion_radius = 0.1f;
  // A box that holds everything that casts a shadow in every frame, so the shadow map's framing
  // does not change between frames.
  Vec3f shadow_bounds_min = Vec3f::Constant(-1.0f);
  Vec3f shadow_bounds_max = Vec3f::Constant(1.0f);
};

}  // namespace dinam
