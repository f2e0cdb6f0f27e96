// libFuzzer target: any bytes as a mesh file, through loading, the scene's checks on the mesh and
// model building. assimp guesses the format from the bytes, as it does for a file with an unknown
// extension. A UserError is a refusal a user would see; anything else is a bug. Crashes inside
// assimp itself are contained by load_mesh_file's child process, not here: they are kept in
// tests/fuzz/assimp-failures/ and replayed through `dinam info` (tests/fuzz/CMakeLists.txt).
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "model/model.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene_description.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dinam;
  try {
    SceneDescription scene;
    scene.duration = 1.0;
    scene.fps = 24.0;
    ObjectDesc object;
    object.name = "fuzzed";
    object.mesh = load_mesh_bytes(data, size, "", FileLoc{"fuzz"});
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
