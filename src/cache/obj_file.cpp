#include "cache/obj_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <utility>

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
      if (info.has_uvs) {
        mesh.corner_uvs.emplace_back(model.face_uv[k].x(), 1.0f - model.face_uv[k].y());
      }
    }
    if (!info.origins.empty()) {
      mesh.face_origin.push_back(model.face_origin[f]);
    }
  }
  mesh.origins = info.origins;
  for (Index b = info.first_bar; b < info.first_bar + info.bar_count; ++b) {
    if (model.bar_on_face[b] == 0) {
      mesh.lines.push_back({model.bar_nodes[2 * b] - first, model.bar_nodes[2 * b + 1] - first});
    }
  }
  return mesh;
}

namespace {

// A name as one OBJ word: spaces and controls made '_'.
std::string obj_name(const std::string& name) {
  std::string word;
  for (const char c : name) {
    word.push_back(static_cast<unsigned char>(c) <= ' ' ? '_' : c);
  }
  return word;
}

}  // namespace

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
  // One `vt` per distinct pair of texture coordinates, in the order the corners meet them.
  std::vector<Index> corner_vt(mesh.corner_uvs.size());
  std::map<std::pair<float, float>, Index> vt_of;
  for (std::size_t c = 0; c < mesh.corner_uvs.size(); ++c) {
    const std::pair<float, float> uv{mesh.corner_uvs[c].x(), mesh.corner_uvs[c].y()};
    const auto [it, added] = vt_of.emplace(uv, static_cast<Index>(vt_of.size()));
    if (added) {
      fmt::format_to(std::back_inserter(text), "vt {} {}\n", uv.first, uv.second);
    }
    corner_vt[c] = it->second;
  }
  std::size_t corner = 0;
  Index origin = -1;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    // A group and a material line where they change, as the file had them.
    if (!mesh.face_origin.empty() && mesh.face_origin[f] != origin) {
      origin = mesh.face_origin[f];
      const MeshElementOrigin none;
      const MeshElementOrigin& o = origin >= 0 ? mesh.origins[origin] : none;
      fmt::format_to(std::back_inserter(text), "g {}\nusemtl {}\n",
                     obj_name(o.groups.empty() ? mesh.name : o.groups.back()),
                     o.material.empty() ? "None" : obj_name(o.material));
    }
    text.push_back('f');
    for (const Index id : mesh.faces[f]) {
      if (corner_vt.empty()) {
        fmt::format_to(std::back_inserter(text), " {}", id + 1);
      } else {
        fmt::format_to(std::back_inserter(text), " {}/{}", id + 1, corner_vt[corner++] + 1);
      }
    }
    text.push_back('\n');
  }
  for (const auto& [a, b] : mesh.lines) {
    fmt::format_to(std::back_inserter(text), "l {} {}\n", a + 1, b + 1);
  }
  write_output_file(path, std::string_view(text.data(), text.size()), "the rest mesh");
}

}  // namespace dinam
