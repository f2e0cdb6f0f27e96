#pragma once
// The off-screen buffers a frame is drawn through. Each instant of the frame is drawn in linear
// colour with a wide range (half floats, multisampled when asked), resolved to a colour and a
// depth texture that later passes read (ambient occlusion into its own texture), and added to
// the frame's sum (single floats, so that adding n equal instants of weight 1/n gives the
// instant back exactly). The finishing pass maps the sum to the display.
namespace dinam {

class FrameTargets {
 public:
  // `samples` 1 draws straight into the resolved textures.
  FrameTargets(int width, int height, int samples, bool ambient_occlusion);
  ~FrameTargets();
  FrameTargets(const FrameTargets&) = delete;
  FrameTargets& operator=(const FrameTargets&) = delete;

  void bind_scene() const;  // the target of one instant's drawing
  void resolve() const;     // its samples into color_texture() and depth_texture()
  void bind_occlusion() const;
  void bind_sum() const;

  unsigned color_texture() const { return color_texture_; }
  unsigned depth_texture() const { return depth_texture_; }
  unsigned occlusion_texture() const { return occlusion_texture_; }
  unsigned sum_texture() const { return sum_texture_; }

 private:
  int width_;
  int height_;
  unsigned multisampled_framebuffer_ = 0, multisampled_color_ = 0, multisampled_depth_ = 0;
  unsigned resolved_framebuffer_ = 0, color_texture_ = 0, depth_texture_ = 0;
  unsigned occlusion_framebuffer_ = 0, occlusion_texture_ = 0;
  unsigned sum_framebuffer_ = 0, sum_texture_ = 0;
};

}  // namespace dinam
