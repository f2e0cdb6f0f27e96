// The draw list and each instant's positions, uploaded to OpenGL's buffers for OsmesaRenderer:
// the primitives once, the instance attributes of bars and joints and the surfaces' vertices
// per instant.
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string_view>

#include "render/cyclorama_mesh.hpp"
#include "render/osmesa_renderer.hpp"
#include "render/primitive_meshes.hpp"

namespace dinam {
namespace {

// The anisotropic filtering textures get: up to 8 samples along a footprint, where the driver has
// the extension (core in OpenGL 4.6; Mesa's llvmpipe has it), else 1 (none).
float texture_anisotropy() {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* name =
        reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (name != nullptr && (std::string_view(name) == "GL_ARB_texture_filter_anisotropic" ||
                            std::string_view(name) == "GL_EXT_texture_filter_anisotropic")) {
      GLfloat most = 1.0f;
      glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &most);
      return std::min(8.0f, most);
    }
  }
  return 1.0f;
}

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

// Declares float attributes from one buffer starting at `first_location`, of the given sizes,
// per instance (divisor 1) or per vertex (divisor 0).
void attributes(unsigned vbo, unsigned first_location, std::initializer_list<int> sizes,
                unsigned divisor) {
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
    glVertexAttribDivisor(location, divisor);
    offset += size;
    ++location;
  }
}

void upload(unsigned vbo, const std::vector<float>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
               GL_STREAM_DRAW);
}

const Finish& finish_of(const std::vector<Finish>& finishes, std::size_t i) {
  static const Finish plastic;  // the default finish
  return i < finishes.size() ? finishes[i] : plastic;
}
}  // namespace

void OsmesaRenderer::create_buffers() {
  // A bar's quad (capsule.vert): four corners drawn as a triangle strip.
  glGenVertexArrays(1, &capsule_vao_);
  glGenBuffers(1, &capsule_vbo_);
  glGenBuffers(1, &bar_instance_vbo_);
  glBindVertexArray(capsule_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, capsule_vbo_);
  const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  glBufferData(GL_ARRAY_BUFFER, sizeof(quad), quad, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), float_offset(0));
  attributes(bar_instance_vbo_, 2, {3, 3, 1, 3, 3}, 1);

  glGenVertexArrays(1, &sphere_vao_);
  glGenBuffers(1, &sphere_vbo_);
  glGenBuffers(1, &sphere_ebo_);
  glGenBuffers(1, &node_instance_vbo_);
  sphere_index_count_ =
      upload_primitive(make_unit_sphere(8, 5), sphere_vao_, sphere_vbo_, sphere_ebo_);
  attributes(node_instance_vbo_, 2, {3, 1, 3, 3}, 1);

  glGenVertexArrays(1, &surface_vao_);
  glGenBuffers(1, &surface_dynamic_vbo_);
  glGenBuffers(1, &surface_static_vbo_);
  glBindVertexArray(surface_vao_);
  attributes(surface_dynamic_vbo_, 0, {3, 3}, 0);
  attributes(surface_static_vbo_, 2, {3, 2, 3}, 0);

  glGenVertexArrays(1, &ground_vao_);
  glGenBuffers(1, &ground_vbo_);
  glBindVertexArray(ground_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, ground_vbo_);
  const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), float_offset(0));

  glGenVertexArrays(1, &backdrop_vao_);
  glGenBuffers(1, &backdrop_vbo_);
  glGenBuffers(1, &backdrop_ebo_);

  glGenVertexArrays(1, &full_screen_vao_);  // its triangle is made from gl_VertexID alone
  glBindVertexArray(0);
}

void OsmesaRenderer::upload_backdrop(const DrawList& list) {
  const Vec3f& c = list.ground_center;
  const Vec3f& n = list.ground_normal;
  const std::vector<float> shape = {c.x(),
                                    c.y(),
                                    c.z(),
                                    n.x(),
                                    n.y(),
                                    n.z(),
                                    list.backdrop_radius,
                                    list.backdrop_curve,
                                    list.backdrop_height};
  if (shape == backdrop_shape_) {
    return;
  }
  backdrop_shape_ = shape;
  backdrop_index_count_ = upload_primitive(
      make_cyclorama(c, n, list.backdrop_radius, list.backdrop_curve, list.backdrop_height),
      backdrop_vao_, backdrop_vbo_, backdrop_ebo_);
  glBindVertexArray(0);
}

void OsmesaRenderer::upload_static(const DrawList& list) {
  if (static_revision_ == list.revision) {
    return;
  }
  static_revision_ = list.revision;
  // Colour, texture coordinates and finish of every point, for the surfaces.
  std::vector<float> attributes_data;
  attributes_data.reserve(list.point_color.size() * 8);
  for (std::size_t p = 0; p < list.point_color.size(); ++p) {
    const Vec3f& c = list.point_color[p];
    const Eigen::Vector2f uv =
        p < list.point_uv.size() ? list.point_uv[p] : Eigen::Vector2f::Zero();
    const Finish& f = finish_of(list.point_finish, p);
    attributes_data.insert(attributes_data.end(),
                           {c.x(), c.y(), c.z(), uv.x(), uv.y(), f.roughness, f.metallic, f.sheen});
  }
  glBindBuffer(GL_ARRAY_BUFFER, surface_static_vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(attributes_data.size() * sizeof(float)),
               attributes_data.data(), GL_STATIC_DRAW);

  glDeleteBuffers(static_cast<GLsizei>(batch_ebos_.size()), batch_ebos_.data());
  batch_ebos_.assign(list.surfaces.size(), 0);
  batch_index_counts_.clear();
  glBindVertexArray(surface_vao_);
  for (std::size_t b = 0; b < list.surfaces.size(); ++b) {
    glGenBuffers(1, &batch_ebos_[b]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, batch_ebos_[b]);
    const auto& triangles = list.surfaces[b].triangles;
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(Index)),
                 triangles.data(), GL_STATIC_DRAW);
    batch_index_counts_.push_back(static_cast<int>(triangles.size()));
  }
  glBindVertexArray(0);

  glDeleteTextures(static_cast<GLsizei>(texture_ids_.size()), texture_ids_.data());
  texture_ids_.assign(list.textures.size(), 0);
  for (std::size_t t = 0; t < list.textures.size(); ++t) {
    const Image& texture = list.textures[t];
    glGenTextures(1, &texture_ids_[t]);
    glBindTexture(GL_TEXTURE_2D, texture_ids_[t]);
    // Rows top first in the image; OpenGL's v runs up, so v = 0 is the picture's top row.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, texture.width, texture.height, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texture.rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // A cloth seen at a grazing angle: sampling along the long axis of each pixel's footprint
    // keeps its picture sharp there, where the mipmap alone would blur it.
    if (const float anisotropy = texture_anisotropy(); anisotropy > 1.0f) {
      glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, anisotropy);
    }
  }
}

void OsmesaRenderer::upload_frame(const DrawList& list, const std::vector<Vec3f>& given) {
  // The frame's points, then those made from them (a subdivided surface's).
  const std::vector<Vec3f>* all = &given;
  if (list.derived.size() > 0) {
    expanded_positions_.assign(given.begin(), given.end());
    const DerivedPoints& derived = list.derived;
    for (Index k = 0; k < derived.size(); ++k) {
      Vec3f sum = Vec3f::Zero();
      for (Index j = derived.offsets[k]; j < derived.offsets[k + 1]; ++j) {
        sum += derived.weights[j] * given[derived.sources[j]];
      }
      expanded_positions_.push_back(sum);
    }
    all = &expanded_positions_;
  }
  const std::vector<Vec3f>& positions = *all;
  const std::size_t n_segments = list.segment_radius.size();
  bar_instances_.resize(n_segments * kBarFloats);
  for (std::size_t s = 0; s < n_segments; ++s) {
    const Vec3f& p0 = positions[list.segment_points[2 * s]];
    const Vec3f& p1 = positions[list.segment_points[2 * s + 1]];
    const Vec3f& c = list.segment_color[s];
    const Finish& f = finish_of(list.segment_finish, s);
    const float values[kBarFloats] = {
        p0.x(), p0.y(), p0.z(), p1.x(),      p1.y(),     p1.z(), list.segment_radius[s],
        c.x(),  c.y(),  c.z(),  f.roughness, f.metallic, f.sheen};
    std::memcpy(bar_instances_.data() + s * kBarFloats, values, sizeof(values));
  }
  upload(bar_instance_vbo_, bar_instances_);

  node_instances_.clear();
  for (std::size_t p = 0; p < positions.size(); ++p) {
    if (list.point_radius[p] > 0.0f) {
      const Vec3f& x = positions[p];
      const Vec3f& c = list.point_color[p];
      const Finish& f = finish_of(list.point_finish, p);
      node_instances_.insert(node_instances_.end(),
                             {x.x(), x.y(), x.z(), list.point_radius[p], c.x(), c.y(), c.z(),
                              f.roughness, f.metallic, f.sheen});
    }
  }
  upload(node_instance_vbo_, node_instances_);

  if (list.surfaces.empty()) {
    return;
  }
  // Normals follow the motion: area-weighted sums of the current triangle normals.
  point_normals_.assign(positions.size(), Vec3f::Zero());
  for (const SurfaceBatch& batch : list.surfaces) {
    for (std::size_t t = 0; t + 2 < batch.triangles.size(); t += 3) {
      const Index a = batch.triangles[t];
      const Index b = batch.triangles[t + 1];
      const Index c = batch.triangles[t + 2];
      const Vec3f area_normal = (positions[b] - positions[a]).cross(positions[c] - positions[a]);
      point_normals_[a] += area_normal;
      point_normals_[b] += area_normal;
      point_normals_[c] += area_normal;
    }
  }
  surface_vertices_.resize(positions.size() * 6);
  for (std::size_t p = 0; p < positions.size(); ++p) {
    const float length = point_normals_[p].norm();
    const Vec3f n = length > 0.0f ? Vec3f(point_normals_[p] / length) : Vec3f::UnitZ();
    const Vec3f& x = positions[p];
    const float values[6] = {x.x(), x.y(), x.z(), n.x(), n.y(), n.z()};
    std::memcpy(surface_vertices_.data() + p * 6, values, sizeof(values));
  }
  upload(surface_dynamic_vbo_, surface_vertices_);
}

}  // namespace dinam
