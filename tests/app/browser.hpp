#pragma once
// Debian's chromium, headless, as the tests of the page `dinam view` writes run it.
#include <fmt/format.h>

#include <filesystem>
#include <string>

namespace dinam::test {

inline constexpr const char* kChromium = "/usr/bin/chromium";

// Chromium as the machine's probe runs it: no sandbox (it may run as root), no GPU (WebGL on its
// SwiftShader), and none of the background services that would reach for the network; its
// profile in `profile`. The page `dinam view` writes inflates its parts and draws after its load
// event (the browser's DecompressionStream is asynchronous), so chromium's virtual time runs it
// until nothing is left to do (or 30 s of its own time) before --dump-dom or --screenshot.
inline std::string chromium_command(const std::filesystem::path& profile,
                                    const std::string& arguments) {
  return fmt::format(
      "{} --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir='{}' --hide-scrollbars --window-size=480,300 --virtual-time-budget=30000 {}",
      kChromium, profile.string(), arguments);
}

}  // namespace dinam::test
