#include "scene/mesh_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

#include "scene/isolated_import.hpp"
#include "scene/obj_vertex_order.hpp"

namespace dinam {
namespace {

void require_edges(const RawMesh& mesh, const std::string& what, const FileLoc& where) {
  if (!mesh.has_edges()) {
    throw_user_error(where,
                     "{} has no edges (no faces or line elements); a structure needs at least one "
                     "bar",
                     what);
  }
}

}  // namespace

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

RawMesh load_mesh_file(const std::filesystem::path& path, const FileLoc& where) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw_user_error(where, "mesh file '{}' is a folder; name a mesh file in it", path.string());
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw_user_error(where,
                     "mesh file '{}' not found; mesh paths are relative to the folder of the scene "
                     "file",
                     path.string());
  }
  RawMesh mesh;
  try {
    mesh = import_in_child(path, where);
  } catch (const UserError& e) {
    // assimp reads .blend files of Blender 2.7 and older only, and says so in terms of Blender's
    // internal structures ("BlendDNA: Did not find a field named `no` in structure `MVert`").
    if (lower_extension(path) != ".blend") {
      throw;
    }
    const std::string& said = e.message();
    const std::size_t quote = said.find("': ");
    const std::string assimp_said = quote == std::string::npos ? said : said.substr(quote + 3);
    throw_user_error(
        where,
        "cannot read '{}': dinam reads mesh files with assimp, which knows .blend "
        "files of Blender 2.7 and older only (it says: {}). In Blender, select the object and "
        "use File > Export > Wavefront (.obj) with Forward Axis Y and Up Axis Z (then "
        "name the .obj here), or export glTF 2.0 and add 'up_axis: y' to the mesh",
        path.string(), assimp_said);
  }
  if (lower_extension(path) == ".obj") {
    mesh.source_vertex = obj_source_vertices(path, mesh.vertices, mesh.source_vertex_count);
  }
  const std::string what = fmt::format("mesh file '{}'", path.string());
  check_mesh_values(mesh, where, what);  // assimp passes a file's bad vertex ids on
  require_edges(mesh, what, where);
  return mesh;
}

}  // namespace dinam
