#pragma once
// Draws a DrawList off-screen with OSMesa: a sky gradient, a checkered ground, bars as lit
// instanced cylinders and joints as spheres, with 4× multisampling. One renderer draws many
// frames of one size; only the point positions change between frames.
#include <memory>
#include <vector>

#include "core/image.hpp"
#include "render/draw_list.hpp"
#include "render/gl_context.hpp"
#include "render/shader_program.hpp"

namespace dinam {

class OsmesaRenderer {
 public:
  // `samples` is the multisampling count, clamped to what the driver offers; 1 turns it off.
  OsmesaRenderer(int width, int height, int samples = 4);
  ~OsmesaRenderer();
  OsmesaRenderer(const OsmesaRenderer&) = delete;
  OsmesaRenderer& operator=(const OsmesaRenderer&) = delete;

  // Draws `list` with its points at `positions` (n_points) into `image` (resized if needed).
  void render(const DrawList& list, const std::vector<Vec3f>& positions, Image& image);

  int samples() const { return samples_; }

 private:
  void create_buffers();
  void create_framebuffer();

  GlContext context_;
  int samples_;
  std::unique_ptr<ShaderProgram> bar_program_;
  std::unique_ptr<ShaderProgram> node_program_;
  std::unique_ptr<ShaderProgram> ground_program_;
  std::unique_ptr<ShaderProgram> sky_program_;

  unsigned cylinder_vao_ = 0, cylinder_vbo_ = 0, cylinder_ebo_ = 0, bar_instance_vbo_ = 0;
  unsigned sphere_vao_ = 0, sphere_vbo_ = 0, sphere_ebo_ = 0, node_instance_vbo_ = 0;
  unsigned ground_vao_ = 0, ground_vbo_ = 0, sky_vao_ = 0;
  unsigned msaa_fbo_ = 0, msaa_color_ = 0, msaa_depth_ = 0;
  int cylinder_index_count_ = 0;
  int sphere_index_count_ = 0;

  std::vector<float> bar_instances_;   // (n_segments × 10) p0, p1, radius, colour
  std::vector<float> node_instances_;  // (n_joints × 7) centre, radius, colour
};

}  // namespace dinam
