#include "visual/sharp_edges.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dinam {

namespace {

// Disjoint sets over a few triangles (a node's), by their place in its list.
Index find_root(std::vector<Index>& parent, Index i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

}  // namespace

std::vector<Index> split_at_sharp_edges(std::vector<Index>& triangles,
                                        const std::vector<Index>& triangle_face,
                                        const std::vector<Vec3>& x, double sharp_radians,
                                        Index first_new) {
  const auto count = static_cast<Index>(triangle_face.size());
  const std::vector<Index> original = triangles;  // the edges, as the points are renumbered
  std::vector<Vec3> normal(static_cast<std::size_t>(count));
  Index largest = -1;
  for (Index t = 0; t < count; ++t) {
    const Index* c = &triangles[3 * static_cast<std::size_t>(t)];
    const Vec3 n = (x[c[1]] - x[c[0]]).cross(x[c[2]] - x[c[0]]);
    normal[t] = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
    largest = std::max({largest, c[0], c[1], c[2]});
  }
  // Each point's triangle corners, as 3 t + k.
  std::vector<std::vector<Index>> corners_of(static_cast<std::size_t>(largest + 1));
  for (Index corner = 0; corner < 3 * count; ++corner) {
    corners_of[triangles[corner]].push_back(corner);
  }
  const double cos_sharp = sharp_radians < 0.0 ? 2.0 : std::cos(sharp_radians);
  auto smooth_between = [&](Index a, Index b) {
    if (triangle_face[a] == triangle_face[b]) {
      return true;
    }
    return normal[a].dot(normal[b]) >= cos_sharp;
  };
  std::vector<Index> sources;
  std::vector<Index> parent;
  for (Index point = 0; point <= largest; ++point) {
    const std::vector<Index>& corners = corners_of[point];
    parent.resize(corners.size());
    std::iota(parent.begin(), parent.end(), Index{0});
    // Two of the point's triangles that share an edge through it (another corner) and meet
    // smoothly there are one group.
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Index* a = &original[3 * static_cast<std::size_t>(corners[i] / 3)];
      for (std::size_t j = i + 1; j < corners.size(); ++j) {
        const Index* b = &original[3 * static_cast<std::size_t>(corners[j] / 3)];
        bool shares_edge = false;
        for (int p = 0; p < 3; ++p) {
          for (int q = 0; q < 3; ++q) {
            shares_edge = shares_edge || (a[p] != point && a[p] == b[q]);
          }
        }
        if (shares_edge && smooth_between(corners[i] / 3, corners[j] / 3)) {
          parent[find_root(parent, static_cast<Index>(j))] =
              find_root(parent, static_cast<Index>(i));
        }
      }
    }
    // The group of the point's first corner keeps it; every other group a new point.
    std::vector<Index> point_of_root(corners.size(), -1);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Index root = find_root(parent, static_cast<Index>(i));
      if (point_of_root[root] < 0) {
        point_of_root[root] =
            root == find_root(parent, 0) ? point : first_new + static_cast<Index>(sources.size());
        if (point_of_root[root] != point) {
          sources.push_back(point);
        }
      }
      triangles[corners[i]] = point_of_root[root];
    }
  }
  return sources;
}

}  // namespace dinam
