#pragma once
// Surfaces shaded flat or with sharp edges (`shading: flat` or `auto`): a point's normal is the
// mean of its triangles' (render/), so where faces should not blend across an edge, their corners
// there get points of their own, each a copy of the node (a derived point of weight 1).
#include <vector>

#include "core/types.hpp"

namespace dinam {

// Splits the points of `triangles` (n × 3 point ids, rewritten in place; triangle t fanned from
// face triangle_face[t]) so that no two triangles share a point across a sharp edge: every edge
// between two faces where `sharp_radians` < 0 (flat), or where their normals at the positions `x`
// turn by more than `sharp_radians`. The triangles of one face always share theirs. New points
// are numbered from `first_new`; returns each one's source point.
std::vector<Index> split_at_sharp_edges(std::vector<Index>& triangles,
                                        const std::vector<Index>& triangle_face,
                                        const std::vector<Vec3>& x, double sharp_radians,
                                        Index first_new);

}  // namespace dinam
