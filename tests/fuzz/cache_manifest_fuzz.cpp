// libFuzzer target: any bytes as a motion cache's manifest.json, the file every reader of a cache
// (render --cache, view, the farm) trusts first. Reading may refuse them (UserError, as a user
// sees it); anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cache/manifest.hpp"
#include "core/error.hpp"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    dinam::parse_manifest(text, "fuzz/manifest.json");
  } catch (const dinam::UserError&) {
  }
  return 0;
}
