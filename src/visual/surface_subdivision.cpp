#include "visual/surface_subdivision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <utility>

#include "core/error.hpp"

namespace dinam {
namespace {

// A point as a weighted sum of base points, by base id, increasing.
using Combination = std::vector<std::pair<Index, double>>;

// Σ w_k × c_k, merged by base id.
Combination combine(std::initializer_list<std::pair<double, const Combination*>> terms) {
  Combination sum;
  for (const auto& [weight, combination] : terms) {
    for (const auto& [id, w] : *combination) {
      sum.emplace_back(id, weight * w);
    }
  }
  std::sort(sum.begin(), sum.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Combination merged;
  for (const auto& [id, w] : sum) {
    if (!merged.empty() && merged.back().first == id) {
      merged.back().second += w;
    } else {
      merged.emplace_back(id, w);
    }
  }
  return merged;
}

// A border that turns by more than this (its edges meeting at under 150°) has a corner there.
constexpr double kCornerDegrees = 150.0;

std::uint64_t edge_key(Index a, Index b) {
  const auto low = static_cast<std::uint64_t>(std::min(a, b));
  const auto high = static_cast<std::uint64_t>(std::max(a, b));
  return (low << 32) | high;
}

struct Edge {
  Index a = 0;
  Index b = 0;
  std::vector<Index> opposite;  // the third corner of each triangle on it
  Index midpoint = -1;          // its point on the next level
};

// One level of Loop subdivision of `triangles` over `points`; `corner` marks the points a border
// turns at, which stay (it grows with the points: a new point is no corner).
void refine(std::vector<Combination>& points, std::vector<Index>& triangles,
            std::vector<std::uint8_t>& corner) {
  std::unordered_map<std::uint64_t, Edge> edges;
  edges.reserve(triangles.size());
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const Index a = triangles[t + k];
      const Index b = triangles[t + (k + 1) % 3];
      Edge& edge = edges[edge_key(a, b)];
      edge.a = std::min(a, b);
      edge.b = std::max(a, b);
      edge.opposite.push_back(triangles[t + (k + 2) % 3]);
    }
  }
  // Each point's neighbours, and those across creases (edges on one triangle, or on more than
  // two), which refine as curves of their own.
  const std::size_t n = points.size();
  std::vector<std::vector<Index>> neighbours(n);
  std::vector<std::vector<Index>> crease_neighbours(n);
  std::vector<std::uint64_t> keys;
  keys.reserve(edges.size());
  for (const auto& [key, edge] : edges) {
    keys.push_back(key);
  }
  std::sort(keys.begin(), keys.end());  // a fixed order: the same points whatever the hashing
  for (const std::uint64_t key : keys) {
    const Edge& edge = edges[key];
    neighbours[edge.a].push_back(edge.b);
    neighbours[edge.b].push_back(edge.a);
    if (edge.opposite.size() != 2) {
      crease_neighbours[edge.a].push_back(edge.b);
      crease_neighbours[edge.b].push_back(edge.a);
    }
  }
  std::vector<Combination> next(n);
  for (std::size_t v = 0; v < n; ++v) {
    const std::vector<Index>& ring = neighbours[v];
    const std::vector<Index>& crease = crease_neighbours[v];
    // A point on no triangle, and a corner of creases (where a border turns, or creases meet),
    // stays where it is.
    const bool stays = ring.empty() || (!crease.empty() && (crease.size() != 2 || corner[v] != 0));
    if (stays) {
      next[v] = points[v];
    } else if (!crease.empty()) {
      next[v] = combine({{0.75, &points[v]},
                         {0.125, &points[static_cast<std::size_t>(crease[0])]},
                         {0.125, &points[static_cast<std::size_t>(crease[1])]}});
    } else {
      const auto valence = static_cast<double>(ring.size());
      const double c = 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / valence);
      const double beta = (0.625 - c * c) / valence;
      Combination sum = combine({{1.0 - valence * beta, &points[v]}});
      for (const Index u : ring) {
        sum = combine({{1.0, &sum}, {beta, &points[static_cast<std::size_t>(u)]}});
      }
      next[v] = std::move(sum);
    }
  }
  for (const std::uint64_t key : keys) {
    Edge& edge = edges[key];
    const Combination& a = points[static_cast<std::size_t>(edge.a)];
    const Combination& b = points[static_cast<std::size_t>(edge.b)];
    edge.midpoint = static_cast<Index>(next.size());
    if (edge.opposite.size() == 2) {
      next.push_back(combine({{0.375, &a},
                              {0.375, &b},
                              {0.125, &points[static_cast<std::size_t>(edge.opposite[0])]},
                              {0.125, &points[static_cast<std::size_t>(edge.opposite[1])]}}));
    } else {
      next.push_back(combine({{0.5, &a}, {0.5, &b}}));
    }
  }
  std::vector<Index> finer;
  finer.reserve(4 * triangles.size());
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const Index a = triangles[t];
    const Index b = triangles[t + 1];
    const Index c = triangles[t + 2];
    const Index ab = edges[edge_key(a, b)].midpoint;
    const Index bc = edges[edge_key(b, c)].midpoint;
    const Index ca = edges[edge_key(c, a)].midpoint;
    finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
  }
  corner.resize(next.size(), 0);
  points = std::move(next);
  triangles = std::move(finer);
}

}  // namespace

SubdividedSurface subdivide_loop(const std::vector<Index>& triangles, int levels,
                                 const std::vector<Vec3>& rest) {
  DINAM_CHECK(levels >= 1 && triangles.size() % 3 == 0);
  // The base points the triangles use, numbered from 0 in the order they are first met.
  std::unordered_map<Index, Index> local;
  std::vector<Combination> points;
  std::vector<Index> mesh;
  mesh.reserve(triangles.size());
  for (const Index id : triangles) {
    const auto [at, added] = local.try_emplace(id, static_cast<Index>(points.size()));
    if (added) {
      points.push_back({{id, 1.0}});
    }
    mesh.push_back(at->second);
  }
  // A triangle folded onto a line (a torn or degenerate face) has no surface to smooth.
  std::vector<Index> kept;
  for (std::size_t t = 0; t + 2 < mesh.size(); t += 3) {
    if (mesh[t] != mesh[t + 1] && mesh[t + 1] != mesh[t + 2] && mesh[t + 2] != mesh[t]) {
      kept.insert(kept.end(), {mesh[t], mesh[t + 1], mesh[t + 2]});
    }
  }
  // Where a border turns (its two border edges at the point meet at under kCornerDegrees at
  // rest, as at a flag's corners) the point is kept, so the corner is not rounded off.
  std::vector<std::uint8_t> corner(points.size(), 0);
  if (!rest.empty()) {
    std::unordered_map<std::uint64_t, int> uses;
    for (std::size_t t = 0; t + 2 < kept.size(); t += 3) {
      for (int k = 0; k < 3; ++k) {
        ++uses[edge_key(kept[t + k], kept[t + (k + 1) % 3])];
      }
    }
    std::vector<std::vector<Index>> border(points.size());
    for (const auto& [key, count] : uses) {
      if (count == 1) {
        const auto a = static_cast<Index>(key >> 32);
        const auto b = static_cast<Index>(key & 0xffffffffu);
        border[a].push_back(b);
        border[b].push_back(a);
      }
    }
    const double straight = std::cos(kCornerDegrees * std::numbers::pi / 180.0);
    for (std::size_t v = 0; v < points.size(); ++v) {
      if (border[v].size() == 2) {
        const Vec3& x = rest[points[v].front().first];
        const Vec3 u = rest[points[border[v][0]].front().first] - x;
        const Vec3 w = rest[points[border[v][1]].front().first] - x;
        // Straight on: the edges point apart, cos = −1; a corner of 90°: cos = 0.
        corner[v] = u.normalized().dot(w.normalized()) > straight ? 1 : 0;
      }
    }
  }
  for (int level = 0; level < levels; ++level) {
    refine(points, kept, corner);
  }
  SubdividedSurface surface;
  surface.triangles = std::move(kept);
  for (const Combination& point : points) {
    for (const auto& [id, weight] : point) {
      surface.points.sources.push_back(id);
      surface.points.weights.push_back(static_cast<float>(weight));
    }
    surface.points.offsets.push_back(static_cast<Index>(surface.points.sources.size()));
  }
  return surface;
}

}  // namespace dinam
