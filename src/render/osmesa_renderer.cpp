#include "render/osmesa_renderer.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "render/camera.hpp"
#include "render/primitive_meshes.hpp"

namespace dinam {
namespace {

constexpr int kBarFloats = 10;
constexpr int kNodeFloats = 7;
const Vec3f kHorizonColor{0.78f, 0.82f, 0.86f};
const Vec3f kZenithColor{0.30f, 0.45f, 0.68f};

// OpenGL takes buffer offsets as pointers.
const void* float_offset(int floats) {
  const std::uintptr_t bytes = static_cast<std::uintptr_t>(floats) * sizeof(float);
  return reinterpret_cast<const void*>(bytes);  // NOLINT(performance-no-int-to-ptr)
}

// Uploads a primitive into `vao`: attribute 0 position, 1 normal.
int upload_primitive(const PrimitiveMesh& mesh, unsigned vao, unsigned vbo, unsigned ebo) {
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(unsigned)), mesh.indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), float_offset(0));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), float_offset(3));
  return static_cast<int>(mesh.indices.size());
}

// Declares per-instance float attributes starting at `first_location`, of the given sizes.
void instance_attributes(unsigned vbo, unsigned first_location, std::initializer_list<int> sizes) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  int stride = 0;
  for (const int size : sizes) {
    stride += size;
  }
  int offset = 0;
  unsigned location = first_location;
  for (const int size : sizes) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE,
                          static_cast<GLsizei>(stride * sizeof(float)), float_offset(offset));
    glVertexAttribDivisor(location, 1);
    offset += size;
    ++location;
  }
}

void set_vec3(int location, const Vec3f& v) {
  glUniform3f(location, v.x(), v.y(), v.z());
}

}  // namespace

OsmesaRenderer::OsmesaRenderer(int width, int height, int samples)
    : context_(width, height), samples_(std::max(1, samples)) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::min(samples_, static_cast<int>(max_samples));
  bar_program_ = std::make_unique<ShaderProgram>("bar.vert", "lit.frag");
  node_program_ = std::make_unique<ShaderProgram>("node.vert", "lit.frag");
  ground_program_ = std::make_unique<ShaderProgram>("ground.vert", "ground.frag");
  sky_program_ = std::make_unique<ShaderProgram>("sky.vert", "sky.frag");
  create_buffers();
  create_framebuffer();
}

OsmesaRenderer::~OsmesaRenderer() {
  const unsigned buffers[] = {cylinder_vbo_, cylinder_ebo_,      bar_instance_vbo_, sphere_vbo_,
                              sphere_ebo_,   node_instance_vbo_, ground_vbo_};
  glDeleteBuffers(static_cast<GLsizei>(std::size(buffers)), buffers);
  const unsigned arrays[] = {cylinder_vao_, sphere_vao_, ground_vao_, sky_vao_};
  glDeleteVertexArrays(static_cast<GLsizei>(std::size(arrays)), arrays);
  if (msaa_fbo_ != 0) {
    glDeleteFramebuffers(1, &msaa_fbo_);
    const unsigned renderbuffers[] = {msaa_color_, msaa_depth_};
    glDeleteRenderbuffers(2, renderbuffers);
  }
}

void OsmesaRenderer::create_buffers() {
  glGenVertexArrays(1, &cylinder_vao_);
  glGenBuffers(1, &cylinder_vbo_);
  glGenBuffers(1, &cylinder_ebo_);
  glGenBuffers(1, &bar_instance_vbo_);
  cylinder_index_count_ =
      upload_primitive(make_unit_cylinder(10), cylinder_vao_, cylinder_vbo_, cylinder_ebo_);
  instance_attributes(bar_instance_vbo_, 2, {3, 3, 1, 3});

  glGenVertexArrays(1, &sphere_vao_);
  glGenBuffers(1, &sphere_vbo_);
  glGenBuffers(1, &sphere_ebo_);
  glGenBuffers(1, &node_instance_vbo_);
  sphere_index_count_ =
      upload_primitive(make_unit_sphere(8, 5), sphere_vao_, sphere_vbo_, sphere_ebo_);
  instance_attributes(node_instance_vbo_, 2, {3, 1, 3});

  glGenVertexArrays(1, &ground_vao_);
  glGenBuffers(1, &ground_vbo_);
  glBindVertexArray(ground_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, ground_vbo_);
  const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), float_offset(0));

  glGenVertexArrays(1, &sky_vao_);  // the sky triangle is made from gl_VertexID alone
  glBindVertexArray(0);
}

void OsmesaRenderer::create_framebuffer() {
  if (samples_ <= 1) {
    return;
  }
  glGenFramebuffers(1, &msaa_fbo_);
  glGenRenderbuffers(1, &msaa_color_);
  glGenRenderbuffers(1, &msaa_depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, context_.width(),
                                   context_.height());
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24,
                                   context_.width(), context_.height());
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw RuntimeError(fmt::format("cannot create a {}× multisampled framebuffer", samples_));
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void OsmesaRenderer::render(const DrawList& list, const std::vector<Vec3f>& positions,
                            Image& image) {
  DINAM_CHECK(positions.size() == list.point_radius.size());
  const int width = context_.width();
  const int height = context_.height();

  // Camera: near and far planes bracket the scene around the look-at distance.
  const RenderCamera& camera = list.camera;
  const float distance = (camera.look_at - camera.position).norm();
  const float far_plane = std::max(100.0f * distance, 4.0f * list.ground_half_size + distance);
  const Mat4f clip_from_world =
      clip_from_eye(camera.fov_degrees, static_cast<float>(width) / static_cast<float>(height),
                    0.01f * distance, far_plane) *
      eye_from_world(camera);
  const Vec3f light = list.light_direction.normalized();

  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
  glViewport(0, 0, width, height);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  // 1. Sky, behind everything.
  glDisable(GL_DEPTH_TEST);
  sky_program_->use();
  set_vec3(sky_program_->uniform("horizon_color"), kHorizonColor);
  set_vec3(sky_program_->uniform("zenith_color"), kZenithColor);
  glBindVertexArray(sky_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  // 2. Ground.
  if (list.ground_visible) {
    ground_program_->use();
    glUniformMatrix4fv(ground_program_->uniform("clip_from_world"), 1, GL_FALSE,
                       clip_from_world.data());
    // Any orthonormal pair in the plane; the world axis least aligned with the normal seeds it.
    const Vec3f normal = list.ground_normal.normalized();
    const Vec3f seed = std::abs(normal.x()) < 0.9f ? Vec3f::UnitX() : Vec3f::UnitY();
    const Vec3f axis_u = (seed - seed.dot(normal) * normal).normalized();
    set_vec3(ground_program_->uniform("center"), list.ground_center);
    set_vec3(ground_program_->uniform("axis_u"), axis_u);
    set_vec3(ground_program_->uniform("axis_v"), normal.cross(axis_u));
    glUniform1f(ground_program_->uniform("half_size"), list.ground_half_size);
    set_vec3(ground_program_->uniform("eye_position"), camera.position);
    glUniform1f(ground_program_->uniform("fade_distance"), 0.9f * list.ground_half_size);
    glUniform1f(ground_program_->uniform("tile_size"), list.ground_tile);
    set_vec3(ground_program_->uniform("horizon_color"), kHorizonColor);
    glBindVertexArray(ground_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 6);
  }

  // 3. Bars as instanced cylinders.
  const std::size_t n_segments = list.segment_radius.size();
  bar_instances_.resize(n_segments * kBarFloats);
  for (std::size_t s = 0; s < n_segments; ++s) {
    float* out = bar_instances_.data() + s * kBarFloats;
    const Vec3f& p0 = positions[list.segment_points[2 * s]];
    const Vec3f& p1 = positions[list.segment_points[2 * s + 1]];
    const Vec3f& c = list.segment_color[s];
    const float values[kBarFloats] = {
        p0.x(), p0.y(), p0.z(), p1.x(), p1.y(), p1.z(), list.segment_radius[s],
        c.x(),  c.y(),  c.z()};
    std::memcpy(out, values, sizeof(values));
  }
  const auto upload = [](unsigned vbo, const std::vector<float>& data) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                 GL_STREAM_DRAW);
  };
  const auto set_lighting = [&](const ShaderProgram& program) {
    program.use();
    glUniformMatrix4fv(program.uniform("clip_from_world"), 1, GL_FALSE, clip_from_world.data());
    set_vec3(program.uniform("light_direction"), light);
    set_vec3(program.uniform("eye_position"), camera.position);
  };
  if (n_segments > 0) {
    upload(bar_instance_vbo_, bar_instances_);
    set_lighting(*bar_program_);
    glBindVertexArray(cylinder_vao_);
    glDrawElementsInstanced(GL_TRIANGLES, cylinder_index_count_, GL_UNSIGNED_INT, nullptr,
                            static_cast<GLsizei>(n_segments));
  }

  // 4. Joints as instanced spheres.
  node_instances_.clear();
  for (std::size_t p = 0; p < positions.size(); ++p) {
    if (list.point_radius[p] <= 0.0f) {
      continue;
    }
    const Vec3f& x = positions[p];
    const Vec3f& c = list.point_color[p];
    node_instances_.insert(node_instances_.end(),
                           {x.x(), x.y(), x.z(), list.point_radius[p], c.x(), c.y(), c.z()});
  }
  if (!node_instances_.empty()) {
    upload(node_instance_vbo_, node_instances_);
    set_lighting(*node_program_);
    glBindVertexArray(sphere_vao_);
    glDrawElementsInstanced(GL_TRIANGLES, sphere_index_count_, GL_UNSIGNED_INT, nullptr,
                            static_cast<GLsizei>(node_instances_.size() / kNodeFloats));
  }
  glBindVertexArray(0);

  // 5. Resolve the samples into the default framebuffer (the OSMesa buffer), then read it.
  if (msaa_fbo_ != 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
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
}

}  // namespace dinam
