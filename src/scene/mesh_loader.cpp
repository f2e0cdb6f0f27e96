#include "scene/mesh_loader.hpp"

#include <fmt/format.h>

#include <string>
#include <system_error>

#include "scene/isolated_import.hpp"

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
  RawMesh mesh = import_in_child(path, where);
  const std::string what = fmt::format("mesh file '{}'", path.string());
  check_mesh_values(mesh, where, what);  // assimp passes a file's bad vertex ids on
  require_edges(mesh, what, where);
  return mesh;
}

}  // namespace dinam
