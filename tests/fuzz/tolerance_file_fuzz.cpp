// libFuzzer target: any bytes as a goldens folder's tolerances.yaml, read as `snapshot` reads it,
// then asked for a frame's limits and regions. Reading may refuse them (UserError at a line, as a
// user sees it); anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_file.hpp"
#include "snapshot/tolerance_file.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dinam::fuzz::write_input("tolerances.yaml", data, size);
  try {
    const dinam::ToleranceFile file = dinam::read_tolerance_file(dinam::fuzz::fuzz_folder());
    for (const auto& [scene, tolerances] : file.scenes) {
      static_cast<void>(tolerances);
      static_cast<void>(file.for_frame(dinam::ImageTolerance{}, scene, 1));
    }
    static_cast<void>(file.for_frame(dinam::ImageTolerance{}, "any", 7));
  } catch (const dinam::UserError&) {
  }
  return 0;
}
