#pragma once
// Sizes of memory and files as people read them.
#include <fmt/format.h>

#include <cstdint>
#include <string>

namespace dinam {

// "1.23 GB", "456 MB", "789 kB": decimal units, three significant figures.
inline std::string byte_size(std::uint64_t bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  auto value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 999.5 && unit < 6) {
    value /= 1000.0;
    ++unit;
  }
  if (unit == 0) {
    return fmt::format("{} bytes", bytes);
  }
  return fmt::format("{:.3g} {}", value, units[unit]);
}

}  // namespace dinam
