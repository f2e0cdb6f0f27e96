#include "render/frame_targets.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include "core/error.hpp"

namespace dinam {
namespace {

unsigned make_texture(int width, int height, GLenum internal_format, GLenum format, GLenum type) {
  unsigned texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format,
               type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

unsigned make_framebuffer(unsigned color_texture, unsigned depth_texture, const char* what) {
  unsigned framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_texture, 0);
  if (depth_texture != 0) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_texture, 0);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeError(fmt::format("cannot create the {} framebuffer", what));
  }
  return framebuffer;
}

}  // namespace

FrameTargets::FrameTargets(int width, int height, int samples, bool ambient_occlusion)
    : width_(width), height_(height) {
  color_texture_ = make_texture(width, height, GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT);
  depth_texture_ =
      make_texture(width, height, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
  resolved_framebuffer_ = make_framebuffer(color_texture_, depth_texture_, "frame colour");
  if (samples > 1) {
    glGenFramebuffers(1, &multisampled_framebuffer_);
    glGenRenderbuffers(1, &multisampled_color_);
    glGenRenderbuffers(1, &multisampled_depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, multisampled_color_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA16F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, multisampled_depth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, multisampled_framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              multisampled_color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                              multisampled_depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw RuntimeError(fmt::format("cannot create a {}× multisampled framebuffer", samples));
    }
  }
  if (ambient_occlusion) {
    occlusion_texture_ = make_texture(width, height, GL_R8, GL_RED, GL_UNSIGNED_BYTE);
    occlusion_framebuffer_ = make_framebuffer(occlusion_texture_, 0, "ambient occlusion");
  }
  sum_texture_ = make_texture(width, height, GL_RGBA32F, GL_RGBA, GL_FLOAT);
  sum_framebuffer_ = make_framebuffer(sum_texture_, 0, "frame sum");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

FrameTargets::~FrameTargets() {
  const unsigned framebuffers[] = {multisampled_framebuffer_, resolved_framebuffer_,
                                   occlusion_framebuffer_, sum_framebuffer_};
  glDeleteFramebuffers(4, framebuffers);  // names 0 are ignored
  const unsigned renderbuffers[] = {multisampled_color_, multisampled_depth_};
  glDeleteRenderbuffers(2, renderbuffers);
  const unsigned textures[] = {color_texture_, depth_texture_, occlusion_texture_, sum_texture_};
  glDeleteTextures(4, textures);
}

void FrameTargets::bind_scene() const {
  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_framebuffer_ != 0 ? multisampled_framebuffer_
                                                                   : resolved_framebuffer_);
  glViewport(0, 0, width_, height_);
}

void FrameTargets::resolve() const {
  if (multisampled_framebuffer_ == 0) {
    return;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_framebuffer_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_,
                    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FrameTargets::bind_occlusion() const {
  DINAM_CHECK(occlusion_framebuffer_ != 0);
  glBindFramebuffer(GL_FRAMEBUFFER, occlusion_framebuffer_);
  glViewport(0, 0, width_, height_);
}

void FrameTargets::bind_sum() const {
  glBindFramebuffer(GL_FRAMEBUFFER, sum_framebuffer_);
  glViewport(0, 0, width_, height_);
}

}  // namespace dinam
