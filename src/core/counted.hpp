#pragma once
// A count with its noun, singular or plural as the count asks: "1 object", "3 objects".
#include <fmt/format.h>

#include <string>

namespace dinam {

inline std::string counted(long long count, const char* singular, const char* plural = nullptr) {
  return count == 1 ? fmt::format("1 {}", singular)
                    : fmt::format("{} {}", count,
                                  plural != nullptr ? plural : std::string(singular) + "s");
}

}  // namespace dinam
