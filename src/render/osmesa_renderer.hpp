#pragma once
// The Renderer on OSMesa (Mesa's software OpenGL, core profile): a sky gradient, a checkered
// ground that takes shadows, bars as capsules ray-cast in quads (impostors), spheres where a
// list asks for them, mesh faces as
// two-sided surfaces (plain or textured), a shadow map from the sun, multisampled anti-aliasing,
// then (core/look.hpp) ambient occlusion, the average of a frame's instants (motion blur) and tone
// mapping. One renderer draws many frames of one size.
#include <memory>
#include <vector>

#include "core/look.hpp"
#include "render/frame_targets.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/shader_program.hpp"
#include "render/shadow_map.hpp"

namespace dinam {

struct RenderSettings {
  int width = 1280;
  int height = 720;
  int samples = 4;               // multisampling; clamped to what the driver offers, 1 is off
  int shadow_resolution = 2048;  // texels per side of the shadow map; 0 turns shadows off
  LookSettings look;
};

class OsmesaRenderer final : public Renderer {
 public:
  explicit OsmesaRenderer(const RenderSettings& settings);
  ~OsmesaRenderer() override;
  OsmesaRenderer(const OsmesaRenderer&) = delete;
  OsmesaRenderer& operator=(const OsmesaRenderer&) = delete;

  using Renderer::render;
  void render(const DrawList& list, std::span<const FrameSample> samples, Image& image) override;

  int samples() const { return samples_; }

 private:
  // Floats per bar and per joint instance in their buffers (osmesa_buffers.cpp).
  static constexpr int kBarFloats = 13;
  static constexpr int kNodeFloats = 10;
  struct Programs;
  void create_buffers();
  void upload_static(const DrawList& list);
  void upload_frame(const DrawList& list, const std::vector<Vec3f>& positions);
  // The cyclorama's surface, made again when its shape changes.
  void upload_backdrop(const DrawList& list);
  // Where an instant is drawn: for the display (tone mapped, encoded, resolved into OSMesa's
  // buffer); in linear colour into the frame targets' textures; or weighted straight into the
  // frame's sum (an instant of a blurred frame).
  enum class InstantTarget { kDisplay, kLinear, kAdded };
  // One instant, moved by `jitter` pixels and lit from `sun_point` of the sun's disc (in the
  // unit disc). Writes the projection it used.
  void draw_instant(const DrawList& list, const FrameSample& sample, const Eigen::Vector2f& jitter,
                    const Eigen::Vector2f& sun_point, InstantTarget target, float weight,
                    Mat4f& clip_from_eye);
  void draw_sky(const DrawList& list, bool direct);
  void draw_ground(const DrawList& list, const Mat4f& clip_from_world, const RenderCamera& camera,
                   const Mat4f* light_from_world, bool direct, bool depth_only);
  // `orthographic_sight`: the line of sight of an orthographic view (the light's), zero for the
  // camera's; `capsule_depth_offset`: what the capsules add to the depth they write.
  void draw_shapes(const DrawList& list, bool depth_only, const float* clip_from_world,
                   const RenderCamera& camera, const Mat4f* light_from_world, bool direct,
                   const Vec3f& orthographic_sight, float capsule_depth_offset);
  // The lighting uniforms of lighting.glsl; `light_from_world` null when there are no shadows.
  void set_lighting(const ShaderProgram& program, const DrawList& list, const RenderCamera& camera,
                    const Mat4f* light_from_world) const;
  // The uniforms of display.glsl.
  void set_output(const ShaderProgram& program, bool direct) const;
  void draw_occlusion(const DrawList& list, const Mat4f& clip_from_eye);
  // A frame's linear colour (an instant's, or the sum of several) to OSMesa's buffer, dimmed by
  // the occlusion when asked.
  void finish(unsigned frame_color, bool occlusion);
  void read_display(Image& image);

  GlContext context_;
  RenderSettings settings_;
  int samples_ = 1;
  std::unique_ptr<Programs> programs_;
  std::unique_ptr<Programs> jittered_programs_;  // for blurred frames' instants, made when needed
  const Programs* programs_in_use_ = nullptr;
  Vec3f light_direction_ = Vec3f::UnitZ();  // of the instant being drawn
  bool multisampled_target_ = false;        // what the instant is drawn into
  std::unique_ptr<FrameTargets> targets_;
  std::unique_ptr<ShadowMap> shadow_map_;           // null when shadows are off
  std::unique_ptr<ShadowMap> jittered_shadow_map_;  // for blurred frames' instants, when needed

  unsigned capsule_vao_ = 0, capsule_vbo_ = 0, bar_instance_vbo_ = 0;
  unsigned sphere_vao_ = 0, sphere_vbo_ = 0, sphere_ebo_ = 0, node_instance_vbo_ = 0;
  unsigned surface_vao_ = 0, surface_dynamic_vbo_ = 0, surface_static_vbo_ = 0;
  unsigned ground_vao_ = 0, ground_vbo_ = 0, full_screen_vao_ = 0;
  unsigned backdrop_vao_ = 0, backdrop_vbo_ = 0, backdrop_ebo_ = 0;
  int backdrop_index_count_ = 0;
  std::vector<float> backdrop_shape_;  // centre, normal, radius, curve, height it was made for
  int sphere_index_count_ = 0;

  // The revision upload_static last uploaded, so a list is uploaded once and a new one (or new
  // contents) replaces it; 0 is no list's.
  std::uint64_t static_revision_ = 0;
  std::vector<unsigned> batch_ebos_;     // (n_batches)
  std::vector<int> batch_index_counts_;  // (n_batches)
  std::vector<unsigned> texture_ids_;    // (n_textures)

  std::vector<float> bar_instances_;       // (n_segments × 13) p0, p1, radius, colour, finish
  std::vector<float> node_instances_;      // (n_joints × 10) centre, radius, colour, finish
  std::vector<float> surface_vertices_;    // (n_points × 6) position, normal
  std::vector<Vec3f> point_normals_;       // (n_points)
  std::vector<Vec3f> expanded_positions_;  // the frame's points and the derived ones
};

}  // namespace dinam
