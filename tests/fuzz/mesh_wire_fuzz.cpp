// libFuzzer target: any bytes as what the importing child process sends back (scene/mesh_wire.hpp).
// A child that a malformed file has led astray may send anything, so decoding must refuse what is
// not one whole encoding without reading past it; what decodes goes through the checks every mesh
// gets, and encodes again to bytes that decode to the same encoding. A UserError is a refusal a
// user would see; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "scene/mesh_wire.hpp"
#include "scene/raw_mesh.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dinam;
  const std::optional<RawMesh> mesh =
      decode_mesh(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!mesh) {
    return 0;
  }
  const std::string encoded = encode_mesh(*mesh);
  const std::optional<RawMesh> again = decode_mesh(encoded);
  if (!again || encode_mesh(*again) != encoded) {
    std::abort();  // the encoding of a decoded mesh must decode to itself
  }
  try {
    check_mesh_values(*mesh, FileLoc{"fuzz"}, "the decoded mesh");
  } catch (const UserError&) {
  }
  return 0;
}
