#include "render/osmesa_renderer.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "render/camera.hpp"

namespace dinam {
namespace {

// Texture units: 0 for surface textures and the passes' inputs, then the shadow map read two
// ways (lighting.glsl), then the occlusion beside the colour.
constexpr int kShadowCompareUnit = 1;
constexpr int kShadowDepthUnit = 2;
constexpr int kOcclusionUnit = 3;
constexpr int kSceneDepthUnit = 4;
// The depth pre-pass of a blurred instant writes its depths this much farther (8 steps of a
// 24-bit depth buffer): a polygon offset for triangles, added by the shader for the capsules,
// whose depth it writes itself.
constexpr float kPrepassDepthMargin = 8.0f / 16777216.0f;
// How far the ground yields its depths to what lies on it (draw_ground): a polygon offset, on top
// of any of the pass.
constexpr float kGroundYieldFactor = 2.0f;
constexpr float kGroundYieldUnits = 16.0f;

void set_vec3(int location, const Vec3f& v) {
  glUniform3f(location, v.x(), v.y(), v.z());
}

void bind_texture(int unit, unsigned texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  glActiveTexture(GL_TEXTURE0);
}

// The radical inverse of `index` in `base`: a low-discrepancy sequence in [0, 1).
float halton(std::size_t index, std::size_t base) {
  float result = 0.0f;
  float fraction = 1.0f;
  for (; index > 0; index /= base) {
    fraction /= static_cast<float>(base);
    result += fraction * static_cast<float>(index % base);
  }
  return result;
}

bool same_camera(const RenderCamera& a, const RenderCamera& b) {
  return a.position == b.position && a.look_at == b.look_at && a.up == b.up &&
         a.fov_degrees == b.fov_degrees;
}

bool same_instant(const FrameSample& a, const FrameSample& b) {
  return same_camera(a.camera, b.camera) &&
         (a.positions == b.positions || *a.positions == *b.positions);
}

// The #defines that build the look's choices into the shaders (lighting.glsl, display.glsl).
// `jittered`: for the instants of a blurred frame, which each see the sun from a point of its
// disc, so that their mean has the soft shadows, and each takes one shadow tap.
std::string look_defines(const LookSettings& look, bool jittered) {
  std::string defines;
  for (const auto& [on, name] :
       {std::pair{look.soft_shadows && !jittered, "SOFT_SHADOWS"},
        std::pair{jittered || !look.filtered_shadow_edges, "ONE_SHADOW_TAP"},
        std::pair{look.sky_light, "SKY_LIGHT"}, std::pair{look.tone_mapping, "TONE_MAPPING"},
        std::pair{look.transparent_background, "TRANSPARENT_BACKGROUND"}}) {
    defines += on ? fmt::format("#define {}\n", name) : "";
  }
  return defines;
}

// What the lit programs and the programs that write display values splice in, in order.
const std::vector<std::string> kLitIncludes = {"noise.glsl", "display.glsl", "lighting.glsl"};
const std::vector<std::string> kDisplayIncludes = {"noise.glsl", "display.glsl"};

}  // namespace

struct OsmesaRenderer::Programs {
  explicit Programs(const std::string& look)
      : bar("capsule.vert", "capsule.frag", kLitIncludes, look),
        bar_line("capsule.vert", "capsule.frag", kLitIncludes, look + "#define LINE_PASS\n"),
        node("node.vert", "lit.frag", kLitIncludes, look),
        surface("surface.vert", "lit.frag", kLitIncludes, look),
        ground("ground.vert", "ground.frag", kLitIncludes, look),
        backdrop("backdrop.vert", "ground.frag", kLitIncludes, look),
        sky("full_screen.vert", "sky.frag", kDisplayIncludes, look),
        finish("full_screen.vert", "finish.frag", kDisplayIncludes, look) {}

  ShaderProgram bar;
  ShaderProgram bar_line;  // the bars narrower than a pixel, as lines (capsule.vert)
  ShaderProgram node;
  ShaderProgram surface;
  ShaderProgram ground;
  ShaderProgram backdrop;  // the cyclorama, shaded as a plain ground
  ShaderProgram sky;
  ShaderProgram finish;
  ShaderProgram bar_depth{"capsule.vert", "capsule.frag", {}, "#define DEPTH_ONLY\n"};
  ShaderProgram bar_line_depth{
      "capsule.vert", "capsule.frag", {}, "#define DEPTH_ONLY\n#define LINE_PASS\n"};
  ShaderProgram node_depth{"node.vert", "depth.frag"};
  ShaderProgram surface_depth{"surface.vert", "depth.frag"};
  ShaderProgram ground_depth{"ground.vert", "depth.frag"};
  ShaderProgram backdrop_depth{"backdrop.vert", "depth.frag"};
  ShaderProgram occlusion{"full_screen.vert", "ambient_occlusion.frag", {"noise.glsl"}};
};

OsmesaRenderer::OsmesaRenderer(const RenderSettings& settings)
    : context_(settings.width, settings.height), settings_(settings) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(settings.samples, 1, static_cast<int>(max_samples));
  programs_ = std::make_unique<Programs>(look_defines(settings.look, false));
  create_buffers();
  targets_ = std::make_unique<FrameTargets>(context_.width(), context_.height(), samples_);
  if (settings.shadow_resolution > 0) {
    shadow_map_ = std::make_unique<ShadowMap>(settings.shadow_resolution);
  }
}

OsmesaRenderer::~OsmesaRenderer() {
  const unsigned buffers[] = {
      capsule_vbo_,         bar_instance_vbo_,   sphere_vbo_, sphere_ebo_,   node_instance_vbo_,
      surface_dynamic_vbo_, surface_static_vbo_, ground_vbo_, backdrop_vbo_, backdrop_ebo_};
  glDeleteBuffers(static_cast<GLsizei>(std::size(buffers)), buffers);
  glDeleteBuffers(static_cast<GLsizei>(batch_ebos_.size()), batch_ebos_.data());
  glDeleteTextures(static_cast<GLsizei>(texture_ids_.size()), texture_ids_.data());
  const unsigned arrays[] = {capsule_vao_, sphere_vao_,   surface_vao_,
                             ground_vao_,  backdrop_vao_, full_screen_vao_};
  glDeleteVertexArrays(static_cast<GLsizei>(std::size(arrays)), arrays);
}

void OsmesaRenderer::set_lighting(const ShaderProgram& program, const DrawList& list,
                                  const RenderCamera& camera, const Mat4f* light_from_world) const {
  set_vec3(program.uniform("light_direction"), light_direction_);
  set_vec3(program.uniform("eye_position"), camera.position);
  glUniform1i(program.uniform("shadows_enabled"), light_from_world != nullptr ? 1 : 0);
  const float radians = 0.5f * list.light_size_degrees * std::numbers::pi_v<float> / 180.0f;
  glUniform1f(program.uniform("light_tan"), std::tan(radians));
  // Both shadow samplers always name their own units: two sampler types on one unit would make
  // every draw call fail, shadows or not.
  glUniform1i(program.uniform("shadow_map"), kShadowCompareUnit);
  glUniform1i(program.uniform("shadow_depth"), kShadowDepthUnit);
  if (light_from_world != nullptr) {
    glUniformMatrix4fv(program.uniform("light_from_world"), 1, GL_FALSE, light_from_world->data());
  }
  set_vec3(program.uniform("horizon_color"), list.sky_horizon);
  set_vec3(program.uniform("zenith_color"), list.sky_zenith);
}

void OsmesaRenderer::draw_shapes(const DrawList& list, bool depth_only,
                                 const float* clip_from_world, const RenderCamera& camera,
                                 const Mat4f* light_from_world, bool direct,
                                 const Vec3f& orthographic_sight, float capsule_depth_offset) {
  const auto prepare = [&](const ShaderProgram& program) {
    program.use();
    glUniformMatrix4fv(program.uniform("clip_from_world"), 1, GL_FALSE, clip_from_world);
    if (depth_only) {
      return;
    }
    set_lighting(program, list, camera, light_from_world);
    set_output(program, direct);
    glUniform1i(program.uniform("use_texture"), 0);
    glUniform1i(program.uniform("surface_texture"), 0);
  };
  const std::size_t n_segments = list.segment_radius.size();
  if (n_segments > 0) {
    // What a pixel spans where a bar is: radians (perspective), or metres across the viewport's
    // pixels (orthographic: the width the clip transform maps to [−1, 1]).
    GLint viewport[4] = {0, 0, 1, 1};
    glGetIntegerv(GL_VIEWPORT, viewport);
    const bool orthographic = orthographic_sight != Vec3f::Zero();
    const Eigen::Map<const Mat4f> clip(clip_from_world);
    const float pixel_angle =
        orthographic
            ? 2.0f / (clip.block<1, 3>(0, 0).norm() * static_cast<float>(viewport[2]))
            : 2.0f * std::tan(0.5f * camera.fov_degrees * std::numbers::pi_v<float> / 180.0f) /
                  static_cast<float>(context_.height());
    const Mat4f world_from_clip = clip.inverse();
    // The fragment's alpha becomes its samples; those it covers take alpha 1 (it is opaque), so
    // that a pixel's alpha is what covers it, not the fragment's coverage again.
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
    glBindVertexArray(capsule_vao_);
    // The bars as quads, then those narrower than a pixel as lines (capsule.vert).
    for (const bool lines : {false, true}) {
      const Programs& programs = *programs_in_use_;
      const ShaderProgram& program =
          lines ? (depth_only ? programs.bar_line_depth : programs.bar_line)
                : (depth_only ? programs.bar_depth : programs.bar);
      prepare(program);
      set_vec3(program.uniform("view_origin"), camera.position);
      set_vec3(program.uniform("view_direction"), orthographic_sight);
      glUniform1f(program.uniform("depth_offset"), capsule_depth_offset);
      // The capsule's silhouette is decided in the fragment shader, which gives each pixel its
      // covered fraction; multisampling turns that into samples (alpha to coverage).
      glUniform1f(program.uniform("pixel_angle"), pixel_angle);
      glUniform1i(program.uniform("multisampled"), multisampled_target_ ? 1 : 0);
      glUniform1i(program.uniform("line_pass"), lines ? 1 : 0);
      glUniformMatrix4fv(program.uniform("world_from_clip"), 1, GL_FALSE, world_from_clip.data());
      glUniform2f(program.uniform("viewport_size"), static_cast<float>(viewport[2]),
                  static_cast<float>(viewport[3]));
      if (lines) {
        glDrawArraysInstanced(GL_LINES, 0, 2, static_cast<GLsizei>(n_segments));
      } else {
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(n_segments));
      }
    }
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }
  if (!node_instances_.empty()) {
    prepare(depth_only ? programs_in_use_->node_depth : programs_in_use_->node);
    glBindVertexArray(sphere_vao_);
    glDrawElementsInstanced(GL_TRIANGLES, sphere_index_count_, GL_UNSIGNED_INT, nullptr,
                            static_cast<GLsizei>(node_instances_.size() / kNodeFloats));
  }
  if (!list.surfaces.empty()) {
    const ShaderProgram& program =
        depth_only ? programs_in_use_->surface_depth : programs_in_use_->surface;
    prepare(program);
    glBindVertexArray(surface_vao_);
    for (std::size_t b = 0; b < list.surfaces.size(); ++b) {
      const int texture = list.surfaces[b].texture;
      if (!depth_only) {
        glUniform1i(program.uniform("use_texture"), texture >= 0 ? 1 : 0);
        bind_texture(0, texture >= 0 ? texture_ids_[static_cast<std::size_t>(texture)] : 0);
      }
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, batch_ebos_[b]);
      glDrawElements(GL_TRIANGLES, batch_index_counts_[b], GL_UNSIGNED_INT, nullptr);
    }
  }
  glBindVertexArray(0);
}

void OsmesaRenderer::draw_ground(const DrawList& list, const Mat4f& clip_from_world,
                                 const RenderCamera& camera, const Mat4f* light_from_world,
                                 bool direct, bool depth_only) {
  const bool backdrop = list.backdrop_radius > 0.0f;
  if (backdrop) {
    upload_backdrop(list);
  }
  // The ground yields its depths to what lies on it: contact holds a resting cloth a micrometre
  // into the plane (or on it), where its depths and the ground's are equal to the buffer's
  // precision, and the ground would hide it in speckle or whole. Pushed back by a few units of
  // depth and twice the slope, on top of any offset its pass already has, the ground still hides
  // what sinks into it by more than about a millimetre at a few metres.
  const bool offset_before = glIsEnabled(GL_POLYGON_OFFSET_FILL) == GL_TRUE;
  GLfloat factor_before = 0.0f;
  GLfloat units_before = 0.0f;
  if (offset_before) {
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor_before);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &units_before);
  }
  // Any orthonormal pair in the plane; the world axis least aligned with the normal seeds it.
  const Vec3f normal = list.ground_normal.normalized();
  const Vec3f seed = std::abs(normal.x()) < 0.9f ? Vec3f::UnitX() : Vec3f::UnitY();
  const Vec3f axis_u = (seed - seed.dot(normal) * normal).normalized();
  for (const bool wall : {false, true}) {
    if (wall && !backdrop) {
      break;
    }
    const Programs& programs = *programs_in_use_;
    const ShaderProgram& program = wall ? (depth_only ? programs.backdrop_depth : programs.backdrop)
                                        : (depth_only ? programs.ground_depth : programs.ground);
    program.use();
    // The cyclorama keeps the pass's own offset: so it is nearer than the plane where the two
    // overlap (the ring's chords reach a little inside the circle the plane ends on).
    if (wall && !offset_before) {
      glDisable(GL_POLYGON_OFFSET_FILL);
    } else {
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(factor_before + (wall ? 0.0f : kGroundYieldFactor),
                      units_before + (wall ? 0.0f : kGroundYieldUnits));
    }
    glUniformMatrix4fv(program.uniform("clip_from_world"), 1, GL_FALSE, clip_from_world.data());
    if (!wall) {
      set_vec3(program.uniform("center"), list.ground_center);
      set_vec3(program.uniform("axis_u"), axis_u);
      set_vec3(program.uniform("axis_v"), normal.cross(axis_u));
      set_vec3(program.uniform("plane_normal"), normal);
      glUniform1f(program.uniform("half_size"), list.ground_half_size);
    }
    if (!depth_only) {
      glUniform1f(program.uniform("fade_distance"), 0.9f * list.ground_half_size);
      glUniform1f(program.uniform("tile_size"),
                  list.ground_checker && !wall ? list.ground_tile : 0.0f);
      set_vec3(program.uniform("ground_color"), list.ground_color);
      set_vec3(program.uniform("checker_color"), list.ground_checker_color);
      glUniform1f(program.uniform("floor_radius"), wall ? 0.0f : list.backdrop_radius);
      set_vec3(program.uniform("floor_center"), list.ground_center);
      set_vec3(program.uniform("floor_normal"), normal);
      set_lighting(program, list, camera, light_from_world);
      set_output(program, direct);
    }
    if (wall) {
      glBindVertexArray(backdrop_vao_);
      glDrawElements(GL_TRIANGLES, backdrop_index_count_, GL_UNSIGNED_INT, nullptr);
    } else {
      glBindVertexArray(ground_vao_);
      glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    glBindVertexArray(0);
  }
  if (offset_before) {
    glPolygonOffset(factor_before, units_before);
  } else {
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
}

void OsmesaRenderer::set_output(const ShaderProgram& program, bool direct) const {
  glUniform1i(program.uniform("direct_to_display"), direct ? 1 : 0);
  glUniform1f(program.uniform("exposure_scale"), std::exp2(settings_.look.exposure));
}

void OsmesaRenderer::draw_instant(const DrawList& list, const FrameSample& sample,
                                  const Eigen::Vector2f& jitter, const Eigen::Vector2f& sun_point,
                                  InstantTarget target, float weight, Mat4f& clip_from_eye) {
  const RenderCamera& camera = sample.camera;
  const bool direct = target == InstantTarget::kDisplay;
  // The sun's direction, moved to `sun_point` of its disc (unit disc coordinates).
  const Vec3f sun = list.light_direction.normalized();
  const Vec3f seed = std::abs(sun.z()) < 0.9f ? Vec3f::UnitZ() : Vec3f::UnitX();
  const Vec3f across = sun.cross(seed).normalized();
  const float radius =
      std::tan(0.5f * list.light_size_degrees * std::numbers::pi_v<float> / 180.0f);
  light_direction_ =
      (sun + radius * (sun_point.x() * across + sun_point.y() * sun.cross(across))).normalized();
  upload_frame(list, *sample.positions);

  // 1. Shadow map: depth from the light, for everything but the ground.
  //    The instants of a blurred frame take a map of half the resolution: each is one of
  //    several views of the sun, so their mean is smooth where one map's texels would show.
  Mat4f light_from_world = Mat4f::Identity();
  const bool shadows = list.shadows && shadow_map_ != nullptr;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (shadows) {
    const bool added = target == InstantTarget::kAdded;
    if (added && !jittered_shadow_map_) {
      jittered_shadow_map_ =
          std::make_unique<ShadowMap>(std::max(settings_.shadow_resolution / 2, 64));
    }
    ShadowMap& map = added ? *jittered_shadow_map_ : *shadow_map_;
    const Mat4f light_clip = map.begin(list, light_direction_, light_from_world);
    draw_shapes(list, true, light_clip.data(), camera, nullptr, direct, -light_direction_, 0.0f);
    map.end();
    map.bind(kShadowCompareUnit, kShadowDepthUnit);
  } else {
    ShadowMap::unbind(kShadowCompareUnit, kShadowDepthUnit);
  }
  const Mat4f* light = shadows ? &light_from_world : nullptr;

  // 2. The view: near and far planes bracket the scene around the look-at distance; `jitter`
  //    (pixels) moves the picture by a fraction of a pixel.
  const float distance = (camera.look_at - camera.position).norm();
  const float far_plane = std::max(100.0f * distance, 4.0f * list.ground_half_size + distance);
  const auto width = static_cast<float>(context_.width());
  const auto height = static_cast<float>(context_.height());
  Mat4f shift = Mat4f::Identity();
  shift(0, 3) = 2.0f * jitter.x() / width;
  shift(1, 3) = 2.0f * jitter.y() / height;
  clip_from_eye =
      shift * dinam::clip_from_eye(camera.fov_degrees, width / height, 0.01f * distance, far_plane);
  const Mat4f clip_from_world = clip_from_eye * eye_from_world(camera);

  if (target == InstantTarget::kAdded) {
    // 3. Added to the sum: depths first, then each pixel's visible fragment alone is shaded and
    //    added with its weight (no colour buffer of its own, no overdraw shaded, no pass to add
    //    it), then the sky where nothing was added. The depths go a few units of depth farther
    //    (a polygon offset) and the colour pass keeps what is not behind them, since Mesa's
    //    software rasteriser does not give a depth-only program exactly the depths of a shaded
    //    one; the stencil lets only the first such fragment of a pixel add itself.
    targets_->bind_sum_with_depth();
    multisampled_target_ = false;
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 8.0f);
    if (list.ground_visible) {
      draw_ground(list, clip_from_world, camera, nullptr, false, true);
    }
    draw_shapes(list, true, clip_from_world.data(), camera, nullptr, false, Vec3f::Zero(),
                kPrepassDepthMargin);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, weight);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE);
    if (list.ground_visible) {
      draw_ground(list, clip_from_world, camera, light, false, false);
    }
    draw_shapes(list, false, clip_from_world.data(), camera, light, false, Vec3f::Zero(), 0.0f);
    glDisable(GL_DEPTH_TEST);
    draw_sky(list, false);  // where the stencil is still 0
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    return;
  }

  // 3. Sky, behind everything, then the ground, bars, joints and surfaces, lit and shadowed.
  if (direct) {
    targets_->bind_direct();
  } else {
    targets_->bind_linear(true);
  }
  multisampled_target_ = samples_ > 1;
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  draw_sky(list, direct);
  glEnable(GL_DEPTH_TEST);
  if (list.ground_visible) {
    draw_ground(list, clip_from_world, camera, light, direct, false);
  }
  draw_shapes(list, false, clip_from_world.data(), camera, light, direct, Vec3f::Zero(), 0.0f);
  glDisable(GL_DEPTH_TEST);
  if (direct) {
    targets_->resolve_direct();
  } else {
    targets_->resolve_linear();
  }
}

void OsmesaRenderer::draw_sky(const DrawList& list, bool direct) {
  const ShaderProgram& sky = programs_in_use_->sky;
  sky.use();
  set_vec3(sky.uniform("horizon_color"), list.sky_horizon);
  set_vec3(sky.uniform("zenith_color"), list.sky_zenith);
  set_output(sky, direct);
  glBindVertexArray(full_screen_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

void OsmesaRenderer::draw_occlusion(const DrawList& list, const Mat4f& clip_from_eye) {
  const ShaderProgram& program = programs_in_use_->occlusion;
  targets_->bind_occlusion();
  program.use();
  bind_texture(0, targets_->depth_texture());
  glUniform1i(program.uniform("scene_depth"), 0);
  const Mat4f eye_from_clip = clip_from_eye.inverse();
  glUniformMatrix4fv(program.uniform("eye_from_clip"), 1, GL_FALSE, eye_from_clip.data());
  glUniformMatrix4fv(program.uniform("clip_from_eye"), 1, GL_FALSE, clip_from_eye.data());
  glUniform1f(program.uniform("radius"), list.occlusion_radius);
  glUniform2f(program.uniform("pixel_size"), 1.0f / static_cast<float>(context_.width()),
              1.0f / static_cast<float>(context_.height()));
  glBindVertexArray(full_screen_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void OsmesaRenderer::finish(unsigned frame_color, bool occlusion) {
  const ShaderProgram& program = programs_in_use_->finish;
  targets_->bind_display();
  program.use();
  bind_texture(0, frame_color);
  glUniform1i(program.uniform("frame_color"), 0);
  bind_texture(kOcclusionUnit, occlusion ? targets_->occlusion_texture() : 0);
  glUniform1i(program.uniform("occlusion"), kOcclusionUnit);
  glUniform1i(program.uniform("use_occlusion"), occlusion ? 1 : 0);
  bind_texture(kSceneDepthUnit, targets_->depth_texture());
  glUniform1i(program.uniform("scene_depth"), kSceneDepthUnit);
  set_output(program, true);
  glBindVertexArray(full_screen_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

void OsmesaRenderer::read_display(Image& image) {
  const int width = context_.width();
  const int height = context_.height();
  glFinish();
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    throw RuntimeError(fmt::format("OpenGL error 0x{:x} while drawing a frame", error));
  }
  if (image.width != width || image.height != height) {
    image = Image(width, height);
  }
  const std::size_t row_bytes = static_cast<std::size_t>(width) * 4;
  const std::uint8_t* source = context_.pixels().data();
  for (int y = 0; y < height; ++y) {  // OpenGL's bottom row becomes the image's last row
    std::memcpy(image.rgba.data() + static_cast<std::size_t>(height - 1 - y) * row_bytes,
                source + static_cast<std::size_t>(y) * row_bytes, row_bytes);
  }
  if (settings_.look.transparent_background) {
    // The buffer holds colours multiplied by their coverage (multisampling averaged them with the
    // empty background); a PNG's alpha is straight, so they are divided by it again.
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
      const unsigned alpha = image.rgba[i + 3];
      for (std::size_t c = i; c < i + 3; ++c) {
        image.rgba[c] = alpha == 0 ? 0
                                   : static_cast<std::uint8_t>(std::min(
                                         255U, (image.rgba[c] * 255U + alpha / 2) / alpha));
      }
    }
    return;
  }
  // The frame is a picture of the whole scene, sky included, so it is opaque everywhere. The
  // buffer's alpha at the edges of wires is their coverage, not a transparency: written to a PNG
  // it gave them dark fringes over any background.
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
    image.rgba[i] = 255;
  }
}

void OsmesaRenderer::render(const DrawList& list, std::span<const FrameSample> samples,
                            Image& image) {
  DINAM_CHECK(!samples.empty());
  for (const FrameSample& sample : samples) {
    DINAM_CHECK(sample.positions != nullptr &&
                sample.positions->size() + static_cast<std::size_t>(list.derived.size()) ==
                    list.point_radius.size());
  }
  upload_static(list);
  // Instants that show the same picture (a frame at rest) are drawn once: a still frame looks
  // the same with and without motion blur, and costs no more.
  const bool still = std::all_of(samples.begin(), samples.end(), [&](const FrameSample& s) {
    return same_instant(s, samples.front());
  });
  const std::span<const FrameSample> instants = still ? samples.first(1) : samples;
  const bool occlusion = settings_.look.ambient_occlusion;
  Mat4f clip_from_eye;
  const Eigen::Vector2f centre = Eigen::Vector2f::Zero();
  programs_in_use_ = programs_.get();
  if (instants.size() == 1 && !occlusion) {
    draw_instant(list, instants.front(), centre, centre, InstantTarget::kDisplay, 1.0f,
                 clip_from_eye);
    read_display(image);
    return;
  }
  if (instants.size() == 1) {
    // One instant with occlusion: drawn in linear colour, then finished from its texture.
    draw_instant(list, instants.front(), centre, centre, InstantTarget::kLinear, 1.0f,
                 clip_from_eye);
    draw_occlusion(list, clip_from_eye);
    finish(targets_->color_texture(), true);
    read_display(image);
    return;
  }
  if (!jittered_programs_) {
    jittered_programs_ = std::make_unique<Programs>(look_defines(settings_.look, true));
  }
  programs_in_use_ = jittered_programs_.get();
  // Several instants are each drawn once without multisampling, moved by a different fraction
  // of a pixel (Halton points), and with soft shadows lit from a different point of the sun's
  // disc (Vogel's spiral), and added into the frame's sum: their mean is anti-aliased and softly
  // shadowed as well as blurred. The middle instant is drawn last, so that the occlusion comes
  // from its depth.
  targets_->bind_sum();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const float weight = 1.0f / static_cast<float>(instants.size());
  const std::size_t middle = instants.size() / 2;
  for (std::size_t k = 0; k < instants.size(); ++k) {
    const std::size_t i = k < middle ? k : (k + 1 < instants.size() ? k + 1 : middle);
    const Eigen::Vector2f jitter(halton(i + 1, 2) - 0.5f, halton(i + 1, 3) - 0.5f);
    Eigen::Vector2f sun_point = centre;
    if (settings_.look.soft_shadows) {
      const float r =
          std::sqrt((static_cast<float>(i) + 0.5f) / static_cast<float>(instants.size()));
      const float angle = 2.39996323f * static_cast<float>(i);  // the golden angle
      sun_point = {r * std::cos(angle), r * std::sin(angle)};
    }
    draw_instant(list, instants[i], jitter, sun_point, InstantTarget::kAdded, weight,
                 clip_from_eye);
  }
  if (occlusion) {
    draw_occlusion(list, clip_from_eye);
  }
  finish(targets_->sum_texture(), occlusion);
  read_display(image);
}

}  // namespace dinam
