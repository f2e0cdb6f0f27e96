#include "scene/mesh_wire.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace dinam {
namespace {

// The child process sends the mesh to the parent as flat arrays: a count, then the elements.
template <typename T>
void put_array(std::string& out, const T* data, std::size_t count) {
  out.append(reinterpret_cast<const char*>(&count), sizeof(count));
  out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

template <typename T>
bool get_array(std::string_view& in, std::vector<T>& out) {
  std::size_t count = 0;
  if (in.size() < sizeof(count)) {
    return false;
  }
  std::memcpy(&count, in.data(), sizeof(count));
  in.remove_prefix(sizeof(count));
  if (count > in.size() / sizeof(T)) {
    return false;
  }
  out.resize(count);
  if (count > 0) {  // an empty vector's data() may be null, which memcpy must not be given
    std::memcpy(static_cast<void*>(out.data()), in.data(), count * sizeof(T));  // plain numbers
  }
  in.remove_prefix(count * sizeof(T));
  return true;
}

}  // namespace

std::string encode_mesh(const RawMesh& mesh) {
  std::string out;
  put_array(out, mesh.vertices.data(), mesh.vertices.size());
  put_array(out, mesh.uvs.data(), mesh.uvs.size());
  for (const auto* loops : {&mesh.faces, &mesh.lines}) {
    std::vector<Index> flat;  // each loop's length, then its ids
    for (const std::vector<Index>& loop : *loops) {
      flat.push_back(static_cast<Index>(loop.size()));
      flat.insert(flat.end(), loop.begin(), loop.end());
    }
    put_array(out, flat.data(), flat.size());
  }
  const std::string texture = mesh.texture.string();
  put_array(out, texture.data(), texture.size());
  put_array(out, mesh.face_origin.data(), mesh.face_origin.size());
  put_array(out, mesh.line_origin.data(), mesh.line_origin.size());
  // Each origin as its group count, then its material and groups as zero-ended names.
  std::vector<Index> group_counts;
  std::vector<char> names;
  for (const MeshElementOrigin& origin : mesh.origins) {
    group_counts.push_back(static_cast<Index>(origin.groups.size()));
    names.insert(names.end(), origin.material.begin(), origin.material.end());
    names.push_back('\0');
    for (const std::string& group : origin.groups) {
      names.insert(names.end(), group.begin(), group.end());
      names.push_back('\0');
    }
  }
  put_array(out, group_counts.data(), group_counts.size());
  put_array(out, names.data(), names.size());
  const std::vector<double> unit(mesh.metres_per_unit ? 1 : 0, mesh.metres_per_unit.value_or(0.0));
  put_array(out, unit.data(), unit.size());
  return out;
}

namespace {

// Reads the origins `encode_mesh` wrote: each one's material, then its groups.
bool get_origins(const std::vector<Index>& group_counts, const std::vector<char>& names,
                 RawMesh& mesh) {
  std::size_t at = 0;
  auto next_name = [&](std::string& name) {
    const auto end = std::find(names.begin() + static_cast<std::ptrdiff_t>(at), names.end(), '\0');
    if (end == names.end()) {
      return false;
    }
    name.assign(names.begin() + static_cast<std::ptrdiff_t>(at), end);
    at = static_cast<std::size_t>(end - names.begin()) + 1;
    return true;
  };
  for (const Index count : group_counts) {
    MeshElementOrigin& origin = mesh.origins.emplace_back();
    if (!next_name(origin.material)) {
      return false;
    }
    // Each group's name takes at least its zero end: a count beyond the bytes left is false, and
    // must not make room for it first (fuzzing found 134 million groups, 4 GB of strings).
    if (count < 0 || static_cast<std::size_t>(count) > names.size() - at) {
      return false;
    }
    origin.groups.resize(static_cast<std::size_t>(count));
    for (std::string& group : origin.groups) {
      if (!next_name(group)) {
        return false;
      }
    }
  }
  return at == names.size();
}

}  // namespace

std::optional<RawMesh> decode_mesh(std::string_view in) {
  RawMesh mesh;
  std::vector<Index> flat[2];
  std::vector<char> texture;
  std::vector<Index> group_counts;
  std::vector<char> names;
  std::vector<double> unit;
  if (!get_array(in, mesh.vertices) || !get_array(in, mesh.uvs) || !get_array(in, flat[0]) ||
      !get_array(in, flat[1]) || !get_array(in, texture) || !get_array(in, mesh.face_origin) ||
      !get_array(in, mesh.line_origin) || !get_array(in, group_counts) || !get_array(in, names) ||
      !get_array(in, unit) || !in.empty() || unit.size() > 1 ||
      !get_origins(group_counts, names, mesh)) {
    return std::nullopt;
  }
  if (!unit.empty()) {
    mesh.metres_per_unit = unit.front();
  }
  auto* loops = &mesh.faces;
  for (const std::vector<Index>& ids : flat) {
    for (std::size_t k = 0; k < ids.size();) {
      const auto length = static_cast<std::size_t>(ids[k]);
      if (length > ids.size() - k - 1) {
        return std::nullopt;
      }
      loops->emplace_back(ids.begin() + static_cast<std::ptrdiff_t>(k + 1),
                          ids.begin() + static_cast<std::ptrdiff_t>(k + 1 + length));
      k += 1 + length;
    }
    loops = &mesh.lines;
  }
  mesh.texture = std::string(texture.begin(), texture.end());
  return mesh;
}

}  // namespace dinam
