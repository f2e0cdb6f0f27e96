#include "render/cyclorama_mesh.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace dinam {

PrimitiveMesh make_cyclorama(const Vec3f& center, const Vec3f& normal, float radius, float curve,
                             float height, int around, int along) {
  const Vec3f up = normal.normalized();
  const Vec3f seed = std::abs(up.x()) < 0.9f ? Vec3f::UnitX() : Vec3f::UnitY();
  const Vec3f axis_u = (seed - seed.dot(up) * up).normalized();
  const Vec3f axis_v = up.cross(axis_u);
  // The profile, outwards and up: (distance from the axis, height, the normal's outward and up
  // parts). The quarter circle's centre is at (radius, curve); the wall goes on straight up.
  struct ProfilePoint {
    float out;
    float rise;
    float normal_out;
    float normal_up;
  };
  std::vector<ProfilePoint> profile;
  for (int k = 0; k <= along; ++k) {
    const float angle =
        0.5f * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(along);
    profile.push_back({radius + curve * std::sin(angle), curve * (1.0f - std::cos(angle)),
                       -std::sin(angle), std::cos(angle)});
  }
  profile.push_back({radius + curve, std::max(height, curve), -1.0f, 0.0f});

  PrimitiveMesh mesh;
  const auto rows = static_cast<unsigned>(profile.size());
  for (int a = 0; a <= around; ++a) {
    const float angle =
        2.0f * std::numbers::pi_v<float> * static_cast<float>(a) / static_cast<float>(around);
    const Vec3f outward = std::cos(angle) * axis_u + std::sin(angle) * axis_v;
    for (const ProfilePoint& p : profile) {
      const Vec3f position = center + p.out * outward + p.rise * up;
      const Vec3f n = p.normal_out * outward + p.normal_up * up;
      mesh.vertices.insert(mesh.vertices.end(),
                           {position.x(), position.y(), position.z(), n.x(), n.y(), n.z()});
    }
  }
  for (unsigned a = 0; a < static_cast<unsigned>(around); ++a) {
    for (unsigned k = 0; k + 1 < rows; ++k) {
      const unsigned here = a * rows + k;
      const unsigned next = here + rows;
      mesh.indices.insert(mesh.indices.end(), {here, next, here + 1, here + 1, next, next + 1});
    }
  }
  return mesh;
}

}  // namespace dinam
