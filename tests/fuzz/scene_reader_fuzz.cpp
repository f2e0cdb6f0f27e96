// libFuzzer target: any bytes as a scene file. Reading may refuse them (UserError, as a user sees
// it); anything else (a crash, a sanitizer report, another exception) is a bug. Mesh paths resolve
// against tests/data, so fuzzed scenes load its meshes too.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "scene/scene_description.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    dinam::read_scene_text(text, DINAM_TEST_DATA_DIR "/fuzz.yaml");
  } catch (const dinam::UserError&) {
  }
  return 0;
}
