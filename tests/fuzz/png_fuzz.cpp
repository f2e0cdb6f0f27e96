// libFuzzer target: any bytes as a PNG file (a texture, a golden image `snapshot` compares with):
// its header's size checked against what its bytes can hold before a row is allocated, then
// decoded to RGBA. Reading may refuse them (UserError or RuntimeError with the file's name, as a
// user sees them); anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "fuzz_file.hpp"
#include "io/png_file.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = dinam::fuzz::write_input("input.png", data, size);
  try {
    const dinam::Image image = dinam::read_png(path);
    if (image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
      __builtin_trap();  // a decoded image whose pixels are not its size
    }
  } catch (const dinam::UserError&) {
  } catch (const dinam::RuntimeError&) {
  }
  return 0;
}
