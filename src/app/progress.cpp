#include "app/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace dinam {

Progress::Progress(int total, bool enabled, std::string stage)
    : total_(total), enabled_(enabled && isatty(STDERR_FILENO) != 0), stage_(std::move(stage)) {}

Progress::~Progress() {
  finish();
}

void Progress::finish() {
  if (drawn_) {
    std::fputc('\n', stderr);
    drawn_ = false;
  }
}

void Progress::update(int done, const std::string& detail) {
  if (!enabled_) {
    return;
  }
  // Redraw at most ten times a second, and always at the end.
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total_ && now - last_ < std::chrono::milliseconds(100)) {
    return;
  }
  last_ = now;
  drawn_ = true;
  fmt::print(stderr, "\r\033[K{} frame {}/{} ({:.0f}%)  {}", stage_, done, total_,
             100.0 * done / total_, detail);
  std::fflush(stderr);
}

}  // namespace dinam
