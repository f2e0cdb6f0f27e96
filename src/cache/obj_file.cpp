#include "cache/obj_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/version.hpp"
#include "model/model.hpp"

namespace dinam {

RestMesh rest_mesh(const Model& model, std::size_t object) {
  const ModelObject& info = model.objects[object];
  RestMesh mesh;
  mesh.name = info.name;
  const Index first = info.first_node;
  const Index end = first + info.node_count;
  mesh.vertices.reserve(static_cast<std::size_t>(info.node_count));
  for (Index i = first; i < end; ++i) {
    mesh.vertices.push_back(model.node_initial_x[i].cast<float>());
  }
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index begin = model.face_offsets[f];
    if (model.node_object[model.face_nodes[begin]] != static_cast<Index>(object)) {
      continue;
    }
    std::vector<Index>& face = mesh.faces.emplace_back();
    for (Index k = begin; k < model.face_offsets[f + 1]; ++k) {
      face.push_back(model.face_nodes[k] - first);
    }
  }
  for (Index b = info.first_bar; b < info.first_bar + info.bar_count; ++b) {
    if (model.bar_on_face[b] == 0) {
      mesh.lines.push_back({model.bar_nodes[2 * b] - first, model.bar_nodes[2 * b + 1] - first});
    }
  }
  return mesh;
}

void write_obj(const std::filesystem::path& path, const RestMesh& mesh) {
  fmt::memory_buffer text;
  fmt::format_to(std::back_inserter(text),
                 "# {}: rest mesh written by dinam {}; {} vertices in node order, {} faces, {} "
                 "lines\no {}\n",
                 mesh.name, kVersion, mesh.vertices.size(), mesh.faces.size(), mesh.lines.size(),
                 mesh.name);
  // fmt writes the shortest decimal that reads back as the same float.
  for (const Vec3f& v : mesh.vertices) {
    fmt::format_to(std::back_inserter(text), "v {} {} {}\n", v.x(), v.y(), v.z());
  }
  for (const std::vector<Index>& face : mesh.faces) {
    text.push_back('f');
    for (const Index id : face) {
      fmt::format_to(std::back_inserter(text), " {}", id + 1);
    }
    text.push_back('\n');
  }
  for (const auto& [a, b] : mesh.lines) {
    fmt::format_to(std::back_inserter(text), "l {} {}\n", a + 1, b + 1);
  }
  write_output_file(path, std::string_view(text.data(), text.size()), "the rest mesh");
}

}  // namespace dinam
