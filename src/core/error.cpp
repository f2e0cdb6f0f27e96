#include "core/error.hpp"

#include <cstdio>
#include <cstdlib>

namespace dinam {

std::string FileLoc::to_string() const {
  if (file.empty()) {
    return {};
  }
  if (line <= 0) {
    return file;
  }
  if (column <= 0) {
    return fmt::format("{}:{}", file, line);
  }
  return fmt::format("{}:{}:{}", file, line, column);
}

UserError::UserError(FileLoc loc, const std::string& message)
    : std::runtime_error(loc.known() ? loc.to_string() + ": " + message : message),
      loc_(std::move(loc)),
      message_(message) {}

void check_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "dinam: internal error: check '%s' failed at %s:%d\n", condition, file,
               line);
  std::abort();
}

}  // namespace dinam
