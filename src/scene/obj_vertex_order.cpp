#include "scene/obj_vertex_order.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>

namespace dinam {
namespace {

struct FileVertex {
  std::array<float, 3> p{};
  Index number = 0;
};

// Reads the numbers of every `v x y z` line (a weight or a vertex colour after them is ignored),
// in single precision: assimp keeps positions as float.
std::vector<FileVertex> read_v_lines(const std::filesystem::path& file) {
  std::vector<FileVertex> found;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) {
      continue;
    }
    FileVertex v;
    v.number = static_cast<Index>(found.size());
    const char* at = line.data() + 2;
    const char* const end = line.data() + line.size();
    for (float& coordinate : v.p) {
      while (at < end && (*at == ' ' || *at == '\t')) {
        ++at;
      }
      double value = 0.0;
      const auto [next, error] = std::from_chars(at, end, value);
      if (error != std::errc()) {
        return {};  // a line this reader does not follow: keep assimp's order rather than guess
      }
      coordinate = static_cast<float>(value);
      at = next;
    }
    found.push_back(v);
  }
  return found;
}

}  // namespace

std::vector<Index> obj_source_vertices(const std::filesystem::path& file,
                                       const std::vector<Vec3>& vertices, Index& vertex_count) {
  std::vector<FileVertex> lines = read_v_lines(file);
  vertex_count = static_cast<Index>(lines.size());
  std::vector<Index> source(vertices.size(), -1);
  if (lines.empty() || vertices.empty()) {
    return source;
  }
  // Sorted by position, then by number, so that equal positions find their first line.
  const auto before = [](const FileVertex& a, const FileVertex& b) {
    return a.p != b.p ? a.p < b.p : a.number < b.number;
  };
  std::sort(lines.begin(), lines.end(), before);
  Vec3 low = vertices.front();
  Vec3 high = vertices.front();
  for (const Vec3& v : vertices) {
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  const float tolerance = static_cast<float>(1e-6 * (high - low).norm());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const FileVertex wanted{
        {static_cast<float>(vertices[k].x()), static_cast<float>(vertices[k].y()),
         static_cast<float>(vertices[k].z())},
        -1};
    // The same float: assimp and this reader round the text alike.
    auto it = std::lower_bound(lines.begin(), lines.end(), wanted, before);
    if (it != lines.end() && it->p == wanted.p) {
      source[k] = it->number;
      continue;
    }
    // Else the nearest in x within the tolerance whose y and z are within it too.
    const FileVertex from{{wanted.p[0] - tolerance, -INFINITY, -INFINITY}, -1};
    for (it = std::lower_bound(lines.begin(), lines.end(), from, before);
         it != lines.end() && it->p[0] <= wanted.p[0] + tolerance; ++it) {
      if (std::abs(it->p[1] - wanted.p[1]) <= tolerance &&
          std::abs(it->p[2] - wanted.p[2]) <= tolerance &&
          (source[k] < 0 || it->number < source[k])) {
        source[k] = it->number;
      }
    }
  }
  return source;
}

}  // namespace dinam
