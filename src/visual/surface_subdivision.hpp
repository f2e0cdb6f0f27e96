#pragma once
// A coarse simulation mesh drawn as the smooth surface it stands for (studios simulate a proxy and
// draw a subdivided surface from it): Loop subdivision (Loop 1987) of a surface's triangles, each
// level splitting every triangle in four and moving every point towards a weighted mean of its
// neighbours, which converges to a surface with continuous normals. Every refined point is a fixed
// weighted sum of the simulated nodes, found once; each frame then only sums (the simulation and
// the motion cache never see the refined points). Edges that bound one triangle (a cloth's
// border) or more than two are kept as creases, refined as curves of their own, so a flag's edge
// stays where its border nodes are.
#include <vector>

#include "core/types.hpp"
#include "render/draw_list.hpp"

namespace dinam {

struct SubdividedSurface {
  DerivedPoints points;          // of the base points the triangles were given over
  std::vector<Index> triangles;  // (n × 3) ids of `points`, from 0
};

// `levels` (≥ 1) of Loop subdivision of `triangles` (ids of base points). With the base points'
// `rest` positions, a point where the border turns (a flag's corner) is kept where it is.
SubdividedSurface subdivide_loop(const std::vector<Index>& triangles, int levels,
                                 const std::vector<Vec3>& rest = {});

}  // namespace dinam
