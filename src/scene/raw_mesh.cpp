#include "scene/raw_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace dinam {

namespace {

// Far beyond any structure dinam can draw or step (a thousand kilometres; 50 million vertices,
// some 10 GB of model), and far below where double precision or 32-bit ids give out.
constexpr double kMaxCoordinate = 1e6;  // m
constexpr std::size_t kMaxMeshVertices = 50'000'000;

}  // namespace

namespace {

bool origin_has(const MeshElementOrigin& origin, MeshNameKind kind, const std::string& name) {
  return kind == MeshNameKind::kMaterial
             ? origin.material == name
             : std::find(origin.groups.begin(), origin.groups.end(), name) != origin.groups.end();
}

}  // namespace

MeshElementIds elements_named(const RawMesh& mesh, MeshNameKind kind, const std::string& name) {
  MeshElementIds ids;
  for (std::size_t f = 0; f < mesh.face_origin.size(); ++f) {
    if (origin_has(mesh.origins[mesh.face_origin[f]], kind, name)) {
      ids.faces.push_back(static_cast<Index>(f));
    }
  }
  for (std::size_t l = 0; l < mesh.line_origin.size(); ++l) {
    if (origin_has(mesh.origins[mesh.line_origin[l]], kind, name)) {
      ids.lines.push_back(static_cast<Index>(l));
    }
  }
  return ids;
}

std::vector<std::string> element_names(const RawMesh& mesh, MeshNameKind kind) {
  std::vector<std::string> names;
  auto add = [&names](const std::string& name) {
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) {
      names.push_back(name);
    }
  };
  for (const auto* ids : {&mesh.face_origin, &mesh.line_origin}) {
    for (const Index id : *ids) {
      const MeshElementOrigin& origin = mesh.origins[id];
      if (kind == MeshNameKind::kMaterial) {
        add(origin.material);
      } else {
        std::for_each(origin.groups.begin(), origin.groups.end(), add);
      }
    }
  }
  return names;
}

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
  for (const auto* ids : {&mesh.face_origin, &mesh.line_origin}) {
    const std::size_t count = ids == &mesh.face_origin ? mesh.faces.size() : mesh.lines.size();
    const bool consistent =
        ids->empty() ||
        (ids->size() == count && std::all_of(ids->begin(), ids->end(), [&](Index id) {
           return id >= 0 && static_cast<std::size_t>(id) < mesh.origins.size();
         }));
    if (!consistent) {
      throw_user_error(where, "the materials and groups of {} do not match its elements; mend it",
                       what);
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

Placement fit_to_size(double size, RawMesh& mesh) {
  // The box of the vertices that some face or line uses: a file's stray points do not count.
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto* loops : {&mesh.faces, &mesh.lines}) {
    for (const auto& loop : *loops) {
      for (const Index v : loop) {
        used[static_cast<std::size_t>(v)] = true;
      }
    }
  }
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (used[v]) {
      lo = lo.cwiseMin(mesh.vertices[v]);
      hi = hi.cwiseMax(mesh.vertices[v]);
    }
  }
  const double extent = (hi - lo).maxCoeff();
  if (!(extent > 0.0) || !std::isfinite(extent)) {
    return {};  // no edge, or a single point: the mesh checks say so
  }
  const double factor = size / extent;
  const Vec3 bottom_centre{0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z()};
  for (Vec3& p : mesh.vertices) {
    p = (p - bottom_centre) * factor;
  }
  return {factor * Mat3::Identity(), -factor * bottom_centre};
}

}  // namespace dinam
