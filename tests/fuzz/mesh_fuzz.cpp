// libFuzzer target: any bytes as a mesh file, through the path a scene's mesh file takes: written
// to a file, imported by assimp in a child process (scene/isolated_import.hpp), sent back in the
// wire form (scene/mesh_wire.hpp), checked, and built into a model. assimp guesses the format from
// the bytes, as it does for a file with an unknown extension. A UserError is a refusal a user would
// see; anything else is a bug. A crash inside assimp is the child's and becomes a UserError: such
// files are kept in tests/fuzz/assimp-failures/ and replayed through `dinam info`
// (tests/fuzz/CMakeLists.txt). The child's coverage does not reach libFuzzer; the mesh_wire
// target fuzzes what the parent reads from it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "model/model.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene_description.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dinam;
  try {
    SceneDescription scene;
    scene.duration = 1.0;
    scene.fps = 24.0;
    ObjectDesc object;
    object.name = "fuzzed";
    // No extension: assimp then tries every format it reads against the bytes.
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("dinam-fuzz-mesh-" + std::to_string(getpid()));
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    object.mesh = load_mesh_file(file, FileLoc{"fuzz"});
    check_mesh_values(object.mesh, FileLoc{"fuzz"}, "the fuzzed mesh");
    if (object.mesh.vertices.size() > 100'000) {
      return 0;  // a valid but large model: building it only costs time
    }
    // A rubbery wire, as docs/scene-format.md's example.
    object.material.density = 1000.0;
    object.material.youngs_modulus = 5e7;
    object.material.shear_modulus = 5e7 / 2.6;
    object.material.wire_radius = 0.004;
    object.material.area = 5.0265e-5;
    object.material.area_moment = 2.0106e-10;
    object.material.polar_moment = 4.0212e-10;
    scene.objects.push_back(std::move(object));
    build_model(scene);
  } catch (const UserError&) {
  }
  return 0;
}
