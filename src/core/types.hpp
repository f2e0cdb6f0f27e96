#pragma once
// Vocabulary types shared by every stage. Dynamics runs in double precision, rendering in float.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products and homogeneous coordinates

#include <cstdint>

namespace dinam {

using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;
using Mat3 = Eigen::Matrix3d;
using Index = std::int32_t;

// The world is z-up: gravity defaults to (0, 0, -9.81) m/s², the ground is the plane z = height.
inline const Vec3 kWorldUp{0.0, 0.0, 1.0};

}  // namespace dinam
