#include "render/frame_targets.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>

#include "core/error.hpp"

namespace dinam {
namespace {

unsigned make_texture(int width, int height, GLenum internal_format, GLenum format, GLenum type,
                      GLenum filter) {
  unsigned texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format,
               type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

unsigned make_renderbuffer(int width, int height, int samples, GLenum format) {
  unsigned renderbuffer = 0;
  glGenRenderbuffers(1, &renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  return renderbuffer;
}

// A framebuffer over `color` and `depth` (0 for none), textures or renderbuffers.
unsigned make_framebuffer(unsigned color, unsigned depth, bool renderbuffers, bool stencil,
                          const char* what) {
  unsigned framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  // The depth buffers of the linear targets carry a stencil too (FrameTargets::Target).
  const GLenum depth_attachment = stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
  if (renderbuffers) {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, depth_attachment, GL_RENDERBUFFER, depth);
  } else {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (depth != 0) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, depth_attachment, GL_TEXTURE_2D, depth, 0);
    }
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeError(fmt::format("cannot create the {} framebuffer", what));
  }
  return framebuffer;
}

}  // namespace

FrameTargets::FrameTargets(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples) {}

FrameTargets::~FrameTargets() {
  for (const Target* target :
       {&direct_multisampled_, &linear_multisampled_, &linear_, &occlusion_, &sum_}) {
    glDeleteFramebuffers(1, &target->framebuffer);  // name 0 is ignored
  }
  glDeleteFramebuffers(1, &sum_with_depth_);
  for (const Target* target : {&direct_multisampled_, &linear_multisampled_}) {
    const unsigned renderbuffers[] = {target->color, target->depth};
    glDeleteRenderbuffers(2, renderbuffers);
  }
  const unsigned textures[] = {linear_.color, linear_.depth, occlusion_.color, sum_.color};
  glDeleteTextures(4, textures);
}

void FrameTargets::bind(const Target& target, int width, int height) const {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glViewport(0, 0, width, height);
}

void FrameTargets::make_multisampled(Target& target, unsigned color_format, bool stencil,
                                     const char* what) const {
  if (target.framebuffer != 0) {
    return;
  }
  target.color = make_renderbuffer(width_, height_, samples_, color_format);
  target.depth = make_renderbuffer(width_, height_, samples_,
                                   stencil ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24);
  target.framebuffer = make_framebuffer(target.color, target.depth, true, stencil, what);
}

void FrameTargets::bind_display() const {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width_, height_);
}

void FrameTargets::bind_direct() {
  if (samples_ <= 1) {
    bind_display();
    return;
  }
  make_multisampled(direct_multisampled_, GL_RGBA8, false, "multisampled display");
  bind(direct_multisampled_, width_, height_);
}

void FrameTargets::resolve_direct() {
  if (samples_ <= 1) {
    return;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, direct_multisampled_.framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FrameTargets::bind_linear(bool multisampled) {
  Target& resolved = linear_;
  if (resolved.framebuffer == 0) {
    resolved.color = make_texture(width_, height_, GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, GL_NEAREST);
    resolved.depth = make_texture(width_, height_, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL,
                                  GL_UNSIGNED_INT_24_8, GL_NEAREST);
    resolved.framebuffer =
        make_framebuffer(resolved.color, resolved.depth, false, true, "frame colour");
  }
  last_linear_multisampled_ = multisampled && samples_ > 1;
  if (!last_linear_multisampled_) {
    bind(resolved, width_, height_);
    return;
  }
  make_multisampled(linear_multisampled_, GL_RGBA16F, true, "multisampled frame colour");
  bind(linear_multisampled_, width_, height_);
}

void FrameTargets::resolve_linear() {
  if (!last_linear_multisampled_) {
    return;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, linear_multisampled_.framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, linear_.framebuffer);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_,
                    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FrameTargets::bind_occlusion() {
  const int width = std::max(width_ / 2, 1);
  const int height = std::max(height_ / 2, 1);
  if (occlusion_.framebuffer == 0) {
    occlusion_.color = make_texture(width, height, GL_R8, GL_RED, GL_UNSIGNED_BYTE, GL_LINEAR);
    occlusion_.framebuffer =
        make_framebuffer(occlusion_.color, 0, false, false, "ambient occlusion");
  }
  bind(occlusion_, width, height);
}

void FrameTargets::bind_sum() {
  if (sum_.framebuffer == 0) {
    sum_.color = make_texture(width_, height_, GL_RGBA32F, GL_RGBA, GL_FLOAT, GL_NEAREST);
    sum_.framebuffer = make_framebuffer(sum_.color, 0, false, false, "frame sum");
  }
  bind(sum_, width_, height_);
}

void FrameTargets::bind_sum_with_depth() {
  if (sum_with_depth_ == 0) {
    bind_linear(false);  // makes the depth texture
    bind_sum();
    sum_with_depth_ =
        make_framebuffer(sum_.color, linear_.depth, false, true, "frame sum and depth");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, sum_with_depth_);
  glViewport(0, 0, width_, height_);
}

}  // namespace dinam
