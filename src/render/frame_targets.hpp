#pragma once
// The off-screen buffers a frame is drawn through, each made the first time it is needed.
//  - Direct: a frame of one instant without ambient occlusion is drawn, tone mapped and encoded
//    by the shaders themselves, into a multisampled RGBA8 buffer resolved into OSMesa's (or
//    straight into OSMesa's without multisampling): the cheapest way.
//  - Linear: otherwise, in linear colour with a wide range. A single instant (with occlusion) is
//    drawn multisampled in half floats and resolved to a colour and a depth texture that later
//    passes read; the instants of a blurred frame are added straight into the frame's sum
//    (single floats), over the depth texture. Ambient occlusion goes into a texture of half the
//    picture's size. The finishing pass maps the colour or the sum to the display.
namespace dinam {

class FrameTargets {
 public:
  FrameTargets(int width, int height, int samples);
  ~FrameTargets();
  FrameTargets(const FrameTargets&) = delete;
  FrameTargets& operator=(const FrameTargets&) = delete;

  void bind_direct();                   // draw a display-ready frame here
  void resolve_direct();                // … and resolve it into OSMesa's buffer
  void bind_linear(bool multisampled);  // draw one instant in linear colour here
  void resolve_linear();  // … and resolve it into color_texture() and depth_texture()
  void bind_occlusion();  // half the picture's size
  void bind_sum();
  void bind_sum_with_depth();  // the sum, over the depth texture: instants added in place
  void bind_display() const;   // OSMesa's buffer

  unsigned color_texture() const { return linear_.color; }
  unsigned depth_texture() const { return linear_.depth; }
  unsigned occlusion_texture() const { return occlusion_.color; }
  unsigned sum_texture() const { return sum_.color; }

 private:
  // A framebuffer and its colour and depth attachments (textures, or multisampled renderbuffers);
  // the linear targets' depth holds a stencil as well, which blurred frames' instants use.
  struct Target {
    unsigned framebuffer = 0;
    unsigned color = 0;
    unsigned depth = 0;
  };
  void bind(const Target& target, int width, int height) const;
  // Makes `target` multisampled at the picture's size, unless it is made already.
  void make_multisampled(Target& target, unsigned color_format, bool stencil,
                         const char* what) const;

  int width_;
  int height_;
  int samples_;
  bool last_linear_multisampled_ = false;
  Target direct_multisampled_;   // renderbuffers
  Target linear_multisampled_;   // renderbuffers
  Target linear_;                // textures
  Target occlusion_;             // texture, no depth
  Target sum_;                   // texture, no depth
  unsigned sum_with_depth_ = 0;  // a framebuffer over sum_'s colour and linear_'s depth
};

}  // namespace dinam
