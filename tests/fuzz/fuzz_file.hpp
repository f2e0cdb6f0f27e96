#pragma once
// What the fuzz targets whose readers take a path share: the input bytes written to a file of a
// folder of this process's own (made once, in memory under /dev/shm where the system has it, else
// under its temporary folder: a disk's writes would halve the executions a second), as a user's
// file would be read.
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace dinam::fuzz {

inline std::filesystem::path fuzz_folder() {
  static const std::filesystem::path folder = [] {
    std::error_code ec;
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    std::string pattern = (base / "dinam-fuzz-XXXXXX").string();
    return std::filesystem::path(mkdtemp(pattern.data()) != nullptr ? pattern : ".");
  }();
  return folder;
}

// Writes `data` to `name` in the process's folder and returns the path.
inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data,
                                         std::size_t size) {
  const std::filesystem::path path = fuzz_folder() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace dinam::fuzz
