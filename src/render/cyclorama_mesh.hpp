#pragma once
// The cyclorama's surface: around `center` in the plane of unit `normal`, a ring that starts
// at `radius` on the plane, rises along a quarter circle of `curve` and goes on up as a wall to
// `height` above the plane. Its normals face the axis, so that from inside it is lit as a
// studio's backdrop; the ground plane (drawn as ever) is the floor within it.
#include "core/types.hpp"
#include "render/primitive_meshes.hpp"

namespace dinam {

// `around` segments round the axis, `along` on the quarter circle (and one up the wall).
PrimitiveMesh make_cyclorama(const Vec3f& center, const Vec3f& normal, float radius, float curve,
                             float height, int around = 128, int along = 16);

}  // namespace dinam
