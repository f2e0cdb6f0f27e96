#include "model/mesh_cleaning.hpp"

#include <algorithm>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dinam {
namespace {

constexpr std::size_t kExamples = 5;

// The loop or chain without consecutive vertices on one welded vertex (for a loop, the last and
// the first too); counts what it took out in `collapsed`.
std::vector<Index> without_repeats(const std::vector<Index>& loop, bool closed,
                                   const std::vector<Index>& welded, Index& collapsed) {
  std::vector<Index> kept;
  kept.reserve(loop.size());
  for (const Index v : loop) {
    if (!kept.empty() && welded[kept.back()] == welded[v]) {
      ++collapsed;
    } else {
      kept.push_back(v);
    }
  }
  if (closed && kept.size() > 1 && welded[kept.back()] == welded[kept.front()]) {
    kept.pop_back();
    ++collapsed;
  }
  return kept;
}

}  // namespace

CleanedMesh clean_mesh(const RawMesh& mesh, const std::vector<Index>& welded) {
  CleanedMesh clean;
  const auto face_count = static_cast<Index>(mesh.faces.size());
  clean.kept_face.assign(mesh.faces.size(), -1);
  // Each face without repeated corners, and its set of welded corners to find duplicates by.
  std::vector<std::vector<Index>> loops(mesh.faces.size());
  std::vector<std::vector<Index>> corners(mesh.faces.size());
  std::vector<bool> usable(mesh.faces.size(), false);
  std::vector<Index> collapsed_of(mesh.faces.size(), 0);
  for (Index f = 0; f < face_count; ++f) {
    loops[f] = without_repeats(mesh.faces[f], true, welded, collapsed_of[f]);
    for (const Index v : loops[f]) {
      corners[f].push_back(welded[v]);
    }
    std::sort(corners[f].begin(), corners[f].end());
    corners[f].erase(std::unique(corners[f].begin(), corners[f].end()), corners[f].end());
    usable[f] = corners[f].size() >= 3;
  }
  // Duplicates: faces with the same welded corners as an earlier one (by id), in any order.
  std::vector<Index> order(mesh.faces.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    return corners[a] != corners[b] ? corners[a] < corners[b] : a < b;
  });
  std::vector<bool> duplicate(mesh.faces.size(), false);
  for (std::size_t k = 1; k < order.size(); ++k) {
    duplicate[order[k]] = usable[order[k]] && corners[order[k]] == corners[order[k - 1]];
  }
  for (Index f = 0; f < face_count; ++f) {
    if (!usable[f] || duplicate[f]) {
      ++(usable[f] ? clean.duplicate_faces : clean.degenerate_faces);
      if (clean.dropped_examples.size() < kExamples) {
        clean.dropped_examples.push_back(f);
      }
      continue;
    }
    clean.collapsed_sides += collapsed_of[f];
    clean.kept_face[f] = static_cast<Index>(clean.faces.size());
    clean.faces.push_back(std::move(loops[f]));
  }
  clean.kept_line.assign(mesh.lines.size(), -1);
  for (std::size_t l = 0; l < mesh.lines.size(); ++l) {
    Index collapsed = 0;
    std::vector<Index> chain = without_repeats(mesh.lines[l], false, welded, collapsed);
    if (chain.size() < 2) {
      ++clean.degenerate_lines;
      continue;
    }
    clean.collapsed_sides += collapsed;
    clean.kept_line[l] = static_cast<Index>(clean.lines.size());
    clean.lines.push_back(std::move(chain));
  }
  // Welded vertices on no kept face or line: points of the file that are no node.
  std::vector<char> listed(mesh.vertices.size(), 0);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Index w : welded) {
    listed[static_cast<std::size_t>(w)] = 1;
  }
  for (const auto* elements : {&clean.faces, &clean.lines}) {
    for (const auto& element : *elements) {
      for (const Index v : element) {
        used[static_cast<std::size_t>(welded[v])] = 1;
      }
    }
  }
  for (std::size_t w = 0; w < listed.size(); ++w) {
    clean.isolated_vertices += listed[w] != 0 && used[w] == 0 ? 1 : 0;
  }
  return clean;
}

std::string CleanedMesh::summary() const {
  std::vector<std::string> parts;
  if (degenerate_faces > 0) {
    parts.push_back(
        fmt::format("{} degenerate face{} (fewer than three distinct corners once "
                    "coincident vertices are welded)",
                    degenerate_faces, degenerate_faces == 1 ? "" : "s"));
  }
  if (duplicate_faces > 0) {
    parts.push_back(fmt::format("{} duplicate face{} (the same corners as an earlier one)",
                                duplicate_faces, duplicate_faces == 1 ? "" : "s"));
  }
  if (collapsed_sides > 0) {
    parts.push_back(fmt::format("{} zero-length side{} of faces and lines", collapsed_sides,
                                collapsed_sides == 1 ? "" : "s"));
  }
  if (degenerate_lines > 0) {
    parts.push_back(fmt::format("{} line{} of a single point", degenerate_lines,
                                degenerate_lines == 1 ? "" : "s"));
  }
  if (isolated_vertices > 0) {
    parts.push_back(fmt::format("{} vertex{} on no face or line", isolated_vertices,
                                isolated_vertices == 1 ? "" : "es"));
  }
  std::string text = "dropped " + fmt::format("{}", fmt::join(parts, ", "));
  if (!dropped_examples.empty()) {
    text += fmt::format(
        " (faces {}{})", fmt::join(dropped_examples, ", "),
        degenerate_faces + duplicate_faces > static_cast<Index>(dropped_examples.size()) ? ", …"
                                                                                         : "");
  }
  return text + "; they carry no structure";
}

}  // namespace dinam
