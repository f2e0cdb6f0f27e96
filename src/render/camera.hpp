#pragma once
// Camera matrices, OpenGL conventions (right-handed eye space looking down −z, clip z in [−1, 1]).
#include <Eigen/Core>

#include "render/draw_list.hpp"

namespace dinam {

using Mat4f = Eigen::Matrix4f;

Mat4f eye_from_world(const RenderCamera& camera);
Mat4f clip_from_eye(float fov_degrees, float aspect, float near_plane, float far_plane);

// Maps a world point to pixel coordinates (x right, y down, origin top-left); used by tests to
// know where a bar must appear.
Eigen::Vector2f pixel_from_world(const RenderCamera& camera, int width, int height,
                                 const Vec3f& world);

}  // namespace dinam
