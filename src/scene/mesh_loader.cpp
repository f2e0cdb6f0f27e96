#include "scene/mesh_loader.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>
#include <system_error>

namespace dinam {
namespace {

// The id in `mesh.origins` of elements of `material` held by `groups`, added if new.
Index origin_id(std::string material, std::vector<std::string> groups, RawMesh& mesh) {
  for (std::size_t k = 0; k < mesh.origins.size(); ++k) {
    if (mesh.origins[k].material == material && mesh.origins[k].groups == groups) {
      return static_cast<Index>(k);
    }
  }
  mesh.origins.push_back({std::move(material), std::move(groups)});
  return static_cast<Index>(mesh.origins.size() - 1);
}

// Appends every mesh a node holds, moved by the node's transform, then recurses into its
// children. A mesh used by two nodes is added twice, as the file means. `groups` holds the names
// of the nodes above this one (an OBJ file's `o` and `g` are nodes below the root).
void add_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_from_node,
              std::vector<std::string> groups, RawMesh& mesh) {
  const aiMatrix4x4 world_from_node = parent_from_node * node.mTransformation;
  if (node.mName.length > 0 && node.mParent != nullptr) {  // the root is named after the file
    groups.emplace_back(node.mName.C_Str());
  }
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh* ai_mesh = scene.mMeshes[node.mMeshes[k]];
    std::vector<std::string> mesh_groups = groups;
    if (ai_mesh->mName.length > 0 && (groups.empty() || groups.back() != ai_mesh->mName.C_Str())) {
      mesh_groups.emplace_back(ai_mesh->mName.C_Str());
    }
    aiString material;
    if (ai_mesh->mMaterialIndex < scene.mNumMaterials) {
      scene.mMaterials[ai_mesh->mMaterialIndex]->Get(AI_MATKEY_NAME, material);
    }
    const Index origin = origin_id(material.C_Str(), std::move(mesh_groups), mesh);
    const auto base = static_cast<Index>(mesh.vertices.size());
    for (unsigned v = 0; v < ai_mesh->mNumVertices; ++v) {
      const aiVector3D p = world_from_node * ai_mesh->mVertices[v];
      mesh.vertices.emplace_back(p.x, p.y, p.z);
      // Texture coordinates with v from the top of the picture (assimp's v runs up).
      const aiVector3D uv =
          ai_mesh->HasTextureCoords(0) ? ai_mesh->mTextureCoords[0][v] : aiVector3D(0, 0, 0);
      mesh.uvs.emplace_back(uv.x, 1.0 - uv.y);
    }
    for (unsigned f = 0; f < ai_mesh->mNumFaces; ++f) {
      const aiFace& face = ai_mesh->mFaces[f];
      std::vector<Index> ids;
      ids.reserve(face.mNumIndices);
      for (unsigned i = 0; i < face.mNumIndices; ++i) {
        ids.push_back(base + static_cast<Index>(face.mIndices[i]));
      }
      // assimp stores a line element as a 2-index face and a point as a 1-index face.
      if (ids.size() == 2) {
        mesh.lines.push_back(std::move(ids));
        mesh.line_origin.push_back(origin);
      } else if (ids.size() >= 3) {
        mesh.faces.push_back(std::move(ids));
        mesh.face_origin.push_back(origin);
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    add_node(scene, *node.mChildren[c], world_from_node, groups, mesh);
  }
}

// The length of the file's unit in metres, where the file states it: FBX gives its unit in
// centimetres ("UnitScaleFactor", 1 for a file in cm, 100 for one in m), and assimp leaves the
// coordinates in that unit. glTF is in metres by definition and Collada's <unit> is applied by
// assimp itself, so neither needs a factor here; formats without units give none.
std::optional<double> metres_per_file_unit(const aiScene& scene) {
  if (scene.mMetaData == nullptr) {
    return std::nullopt;
  }
  double as_double = 0.0;
  float as_float = 0.0f;
  double centimetres = 0.0;
  if (scene.mMetaData->Get("UnitScaleFactor", as_double)) {
    centimetres = as_double;
  } else if (scene.mMetaData->Get("UnitScaleFactor", as_float)) {
    centimetres = as_float;
  }
  if (!(centimetres > 0.0) || !std::isfinite(centimetres)) {
    return std::nullopt;
  }
  return 0.01 * centimetres;
}

// The mesh a file's scene holds; a diffuse texture named by the first material that has one, as
// a PNG file in `folder` (none when `folder` is empty).
RawMesh mesh_from_scene(const aiScene& scene, const std::filesystem::path& folder) {
  RawMesh mesh;
  std::error_code ec;
  for (unsigned m = 0; m < scene.mNumMaterials && mesh.texture.empty() && !folder.empty(); ++m) {
    aiString name;
    if (scene.mMaterials[m]->GetTexture(aiTextureType_DIFFUSE, 0, &name) == AI_SUCCESS &&
        name.length > 0 && name.C_Str()[0] != '*') {  // '*n' names a texture embedded in the file
      const std::filesystem::path texture = folder / name.C_Str();
      if (std::filesystem::is_regular_file(texture, ec) && texture.extension() == ".png") {
        mesh.texture = texture;
      }
    }
  }
  if (scene.mRootNode != nullptr) {
    add_node(scene, *scene.mRootNode, aiMatrix4x4(), {}, mesh);
  }
  mesh.metres_per_unit = metres_per_file_unit(scene);
  return mesh;
}

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

std::string serialize(const RawMesh& mesh) {
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

// Reads the origins `serialize` wrote: each one's material, then its groups.
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
    origin.groups.resize(static_cast<std::size_t>(std::max<Index>(count, 0)));
    if (!next_name(origin.material)) {
      return false;
    }
    for (std::string& group : origin.groups) {
      if (!next_name(group)) {
        return false;
      }
    }
  }
  return at == names.size();
}

bool deserialize(std::string_view in, RawMesh& mesh) {
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
    return false;
  }
  if (!unit.empty()) {
    mesh.metres_per_unit = unit.front();
  }
  auto* loops = &mesh.faces;
  for (const std::vector<Index>& ids : flat) {
    for (std::size_t k = 0; k < ids.size();) {
      const auto length = static_cast<std::size_t>(ids[k]);
      if (length > ids.size() - k - 1) {
        return false;
      }
      loops->emplace_back(ids.begin() + static_cast<std::ptrdiff_t>(k + 1),
                          ids.begin() + static_cast<std::ptrdiff_t>(k + 1 + length));
      k += 1 + length;
    }
    loops = &mesh.lines;
  }
  mesh.texture = std::string(texture.begin(), texture.end());
  return true;
}

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Seconds the importer may take for a file, plus 2 s per megabyte: $DINAM_MESH_IMPORT_TIMEOUT, else
// 60.
double import_time_limit() {
  const char* text = std::getenv("DINAM_MESH_IMPORT_TIMEOUT");
  const double seconds = text != nullptr ? std::strtod(text, nullptr) : 0.0;
  return seconds > 0.0 ? seconds : 60.0;
}

// A malformed header can make assimp reserve memory for 10⁹ vertices and then touch it page by
// page (invalid/OutOfMemory.off of assimp's test files took a minute of system time): the child
// may grow by 2 GiB plus 64 bytes per byte of the file (assimp's own structures for a sound file
// take a few times its size), and never beyond the machine's memory, so such an allocation fails
// at once and assimp reports it. Left out under the sanitizers, whose shadow memory needs
// terabytes of address space.
void limit_address_space(std::uintmax_t file_bytes) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  (void)file_bytes;
#elif defined(__has_feature) && \
    (__has_feature(address_sanitizer) || __has_feature(memory_sanitizer))
  (void)file_bytes;
#else
  const long page = sysconf(_SC_PAGESIZE);
  const long physical_pages = sysconf(_SC_PHYS_PAGES);
  unsigned long mapped_pages = 0;
  if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%lu", &mapped_pages) != 1) {
      mapped_pages = 0;
    }
    std::fclose(statm);
  }
  if (page <= 0 || physical_pages <= 0) {
    return;
  }
  const double growth = std::min(2.0 * 1024 * 1024 * 1024 + 64.0 * static_cast<double>(file_bytes),
                                 static_cast<double>(page) * static_cast<double>(physical_pages));
  const auto bytes =
      static_cast<rlim_t>(static_cast<double>(page) * static_cast<double>(mapped_pages) + growth);
  const rlimit limit{bytes, bytes};
  setrlimit(RLIMIT_AS, &limit);  // best effort: without it the time limit still holds
#endif
}

// Imports `path` in a child process. The child sends 'M' and the mesh, or 'E' and assimp's error.
RawMesh import_in_child(const std::filesystem::path& path, const FileLoc& where) {
  int ends[2] = {-1, -1};
  if (pipe2(ends, O_CLOEXEC) != 0) {
    throw RuntimeError(
        fmt::format("cannot make a pipe to import {}: {}", path.string(), std::strerror(errno)));
  }
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = fork();
  if (pid < 0) {
    close(ends[0]);
    close(ends[1]);
    throw RuntimeError(
        fmt::format("cannot fork to import {}: {}", path.string(), std::strerror(errno)));
  }
  if (pid == 0) {
    close(ends[0]);
    std::error_code size_error;
    limit_address_space(std::filesystem::file_size(path, size_error));
    Assimp::Importer importer;
    // No post-processing at all: triangulating would add diagonals that are not edges of the
    // model, and model/ welds coincident vertices itself. Node transforms are applied here.
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    const bool sent =
        scene == nullptr
            ? write_all(ends[1], 'E' + std::string(importer.GetErrorString()))
            : write_all(ends[1], 'M' + serialize(mesh_from_scene(*scene, path.parent_path())));
    _exit(sent ? 0 : 1);
  }
  close(ends[1]);
  // A malformed file can also make assimp loop for ever (fuzzing found PLY files that do); the
  // child gets a time that no sound file of this size needs, then it is stopped.
  std::error_code ec;
  const double megabytes = static_cast<double>(std::filesystem::file_size(path, ec)) / 1e6;
  const double limit = import_time_limit() + (ec ? 0.0 : 2.0 * megabytes);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit);
  std::string reply;
  std::array<char, 65536> buffer{};
  bool timed_out = false;
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd readable{ends[0], POLLIN, 0};
    const int ready = left.count() > 0 ? poll(&readable, 1, static_cast<int>(left.count())) : 0;
    if (ready < 0 && errno == EINTR) {
      continue;
    }
    if (ready == 0) {
      timed_out = true;
      kill(pid, SIGKILL);
      break;
    }
    const ssize_t n = read(ends[0], buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      break;
    }
    reply.append(buffer.data(), static_cast<std::size_t>(n));
  }
  close(ends[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    throw_user_error(where,
                     "the mesh importer (assimp) did not finish reading '{}' in {:.0f} s, which "
                     "a sound file of its size never needs (a malformed file can make it loop); "
                     "only this file is refused: mend it or convert it to OBJ",
                     path.string(), limit);
  }
  if (WIFSIGNALED(status)) {
    throw_user_error(where,
                     "the mesh importer (assimp) crashed reading '{}' ({}); dinam imports meshes "
                     "apart, so only this file is refused: convert it to OBJ or PLY, or mend it",
                     path.string(), strsignal(WTERMSIG(status)));
  }
  RawMesh mesh;
  if (!reply.empty() && reply.front() == 'E') {
    const std::string error = reply.substr(1);
    throw_user_error(where, "cannot read mesh file '{}': {}{}", path.string(), error,
                     error.find("bad_alloc") != std::string::npos
                         ? " (the file asks for far more memory than its size needs: its counts "
                           "of vertices or faces are wrong; mend it or convert it to OBJ)"
                         : "");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.empty() || reply.front() != 'M' ||
      !deserialize(std::string_view(reply).substr(1), mesh)) {
    throw RuntimeError(fmt::format("importing {} in a child process failed", path.string()));
  }
  return mesh;
}

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

RawMesh load_mesh_bytes(const void* data, std::size_t size, const std::string& extension,
                        const FileLoc& where) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFileFromMemory(data, size, 0, extension.c_str());
  if (scene == nullptr) {
    throw_user_error(where, "cannot read the {} mesh: {}", extension, importer.GetErrorString());
  }
  RawMesh mesh = mesh_from_scene(*scene, {});
  check_mesh_values(mesh, where, "the mesh");
  require_edges(mesh, "the mesh", where);
  return mesh;
}

}  // namespace dinam
