#include "scene/raw_mesh.hpp"

#include <Eigen/Geometry>
#include <numbers>

#include "core/error.hpp"

namespace dinam {

namespace {

// Far beyond any structure dinam can draw or step (a thousand kilometres; 50 million vertices,
// some 10 GB of model), and far below where double precision or 32-bit ids give out.
constexpr double kMaxCoordinate = 1e6;  // m
constexpr std::size_t kMaxMeshVertices = 50'000'000;

}  // namespace

void check_mesh_values(const RawMesh& mesh, const FileLoc& where, const std::string& what) {
  if (mesh.vertices.size() > kMaxMeshVertices) {
    throw_user_error(where,
                     "{} has {} vertices, more than the {} dinam takes (its model would "
                     "need more memory than a machine has); simplify it",
                     what, mesh.vertices.size(), kMaxMeshVertices);
  }
  const auto vertex_count = static_cast<Index>(mesh.vertices.size());
  for (const auto* loops : {&mesh.faces, &mesh.lines}) {
    for (const std::vector<Index>& loop : *loops) {
      for (const Index id : loop) {
        if (id < 0 || id >= vertex_count) {
          throw_user_error(where,
                           "a {} of {} refers to vertex {}, but it has {} vertices (0 to {}); "
                           "mend the mesh file",
                           loops == &mesh.faces ? "face" : "line", what, id, vertex_count,
                           vertex_count - 1);
        }
      }
    }
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    if (!v.allFinite()) {
      throw_user_error(where,
                       "vertex {} of {} is ({}, {}, {}), not a finite point; mend the "
                       "mesh (or its 'scale')",
                       i, what, v.x(), v.y(), v.z());
    }
    if (v.cwiseAbs().maxCoeff() > kMaxCoordinate) {
      throw_user_error(where,
                       "vertex {} of {} is at ({:g}, {:g}, {:g}) m, beyond {:g} m from the "
                       "origin; is the mesh in other units? Give 'scale'",
                       i, what, v.x(), v.y(), v.z(), kMaxCoordinate);
    }
  }
}

bool RawMesh::has_edges() const {
  for (const auto& face : faces) {
    if (face.size() >= 2) {
      return true;
    }
  }
  for (const auto& line : lines) {
    if (line.size() >= 2) {
      return true;
    }
  }
  return false;
}

Mat3 Transform::rotation() const {
  const Vec3 r = rotation_degrees * (std::numbers::pi / 180.0);
  // x is applied first, so it stands rightmost.
  return (Eigen::AngleAxisd(r.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(r.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

Vec3 Transform::world_from_object(const Vec3& p) const {
  return rotation() * p.cwiseProduct(scale) + translation;
}

void apply_transform(const Transform& transform, RawMesh& mesh) {
  const Mat3 r = transform.rotation();
  for (Vec3& p : mesh.vertices) {
    p = r * p.cwiseProduct(transform.scale) + transform.translation;
  }
}

}  // namespace dinam
