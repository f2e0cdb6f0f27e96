#include "render/shadow_map.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace dinam {
namespace {

// The shadow map's view: an orthographic box around the shadow bounds, seen along the light.
// Returns clip_from_world and writes the [0, 1]³ version used to look the map up.
Mat4f light_clip_from_world(const DrawList& list, const Vec3f& direction, Mat4f& light_from_world) {
  const Vec3f center = 0.5f * (list.shadow_bounds_min + list.shadow_bounds_max);
  const float radius =
      std::max(0.5f * (list.shadow_bounds_max - list.shadow_bounds_min).norm(), 1e-3f);
  RenderCamera light;
  light.position = center + 2.0f * radius * direction;
  light.look_at = center;
  light.up = std::abs(direction.z()) < 0.9f ? Vec3f::UnitZ() : Vec3f::UnitX();
  // x, y in [−r, r], depth from r to 3r in front of the light: the map's width and its depth
  // span the same 2r, which the soft shadows' penumbra relies on (lighting.glsl).
  Mat4f ortho = Mat4f::Identity();
  ortho(0, 0) = 1.0f / radius;
  ortho(1, 1) = 1.0f / radius;
  ortho(2, 2) = -1.0f / radius;
  ortho(2, 3) = -2.0f;
  Mat4f clip = ortho * eye_from_world(light);
  Mat4f to_unit = Mat4f::Identity();
  to_unit.topLeftCorner<3, 3>() *= 0.5f;
  to_unit.topRightCorner<3, 1>().setConstant(0.5f);
  light_from_world = to_unit * clip;
  return clip;
}

// A sampler clamped at the edges, filtered by `filter`, comparing depths (≤) or not.
unsigned make_sampler(GLint filter, GLint compare_mode) {
  unsigned sampler = 0;
  glGenSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, compare_mode);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  return sampler;
}

}  // namespace

ShadowMap::ShadowMap(int resolution) : resolution_(resolution) {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, resolution, resolution, 0,
               GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);

  // One texture, two ways of reading it: sampler objects override the texture's own state.
  compare_sampler_ = make_sampler(GL_LINEAR, GL_COMPARE_REF_TO_TEXTURE);
  depth_sampler_ = make_sampler(GL_NEAREST, GL_NONE);

  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    throw RuntimeError(fmt::format("cannot create a {}² shadow map", resolution));
  }
}

ShadowMap::~ShadowMap() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
  const unsigned samplers[] = {compare_sampler_, depth_sampler_};
  glDeleteSamplers(2, samplers);
}

Mat4f ShadowMap::begin(const DrawList& list, const Vec3f& light_direction,
                       Mat4f& light_from_world) {
  Mat4f clip = light_clip_from_world(list, light_direction, light_from_world);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, resolution_, resolution_);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  return clip;
}

void ShadowMap::end() {
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowMap::bind(int compare_unit, int depth_unit) const {
  for (const auto& [unit, sampler] :
       {std::pair{compare_unit, compare_sampler_}, std::pair{depth_unit, depth_sampler_}}) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBindSampler(static_cast<GLuint>(unit), sampler);
  }
  glActiveTexture(GL_TEXTURE0);
}

void ShadowMap::unbind(int compare_unit, int depth_unit) {
  for (const int unit : {compare_unit, depth_unit}) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindSampler(static_cast<GLuint>(unit), 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace dinam
