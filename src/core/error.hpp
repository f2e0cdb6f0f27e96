#pragma once
// Three kinds of error (STYLE.md §6):
//  - UserError: the scene, an asset or an option is wrong. It carries where (file:line:column when
//    known) and what to do about it; app/ prints it once and exits with code 2.
//  - RuntimeError: the input was fine but the run failed (a file could not be written, ffmpeg
//    failed); app/ prints it and exits with code 1.
//  - DINAM_CHECK: an internal invariant; always on, because a silently wrong simulation is worse
//    than a stopped one.
#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace dinam {

// Where a value came from: a file and a 1-based line and column (0 when unknown).
struct FileLoc {
  std::string file;
  int line = 0;
  int column = 0;

  bool known() const { return !file.empty(); }
  // "file:line:column", "file" alone when the position is unknown, "" when nothing is known.
  std::string to_string() const;
};

class UserError : public std::runtime_error {
 public:
  UserError(FileLoc loc, const std::string& message);
  const FileLoc& loc() const { return loc_; }
  const std::string& message() const { return message_; }

 private:
  FileLoc loc_;
  std::string message_;
};

class RuntimeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A RuntimeError in writing a file (a full disk, a quota, a folder that became read-only): the
// commands add where to free space or write instead.
class WriteError : public RuntimeError {
 public:
  using RuntimeError::RuntimeError;
};

template <typename... Args>
[[noreturn]] void throw_user_error(const FileLoc& loc, fmt::format_string<Args...> format,
                                   Args&&... args) {
  throw UserError(loc, fmt::format(format, std::forward<Args>(args)...));
}

[[noreturn]] void check_failed(const char* condition, const char* file, int line);

}  // namespace dinam

#define DINAM_CHECK(condition)                               \
  do {                                                       \
    if (!(condition)) {                                      \
      ::dinam::check_failed(#condition, __FILE__, __LINE__); \
    }                                                        \
  } while (false)
