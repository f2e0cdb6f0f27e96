#include "scene/raw_mesh.hpp"

#include <Eigen/Geometry>
#include <numbers>

namespace dinam {

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
