#include "run/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace dinam {

namespace {

// In a log, a line at least this often while frames are being done.
constexpr std::chrono::seconds kLogInterval{30};

}  // namespace

Progress::Progress(int total, bool enabled, std::string stage)
    : total_(total),
      enabled_(enabled && total > 0),
      terminal_(isatty(STDERR_FILENO) != 0),
      stage_(std::move(stage)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

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
  if (terminal_) {
    update_terminal(done, detail);
  } else {
    update_log(done, detail);
  }
}

void Progress::update_terminal(int done, const std::string& detail) {
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

void Progress::update_log(int done, const std::string& detail) {
  const auto now = std::chrono::steady_clock::now();
  const int tenths = 10 * done / total_;
  if (tenths <= tenths_logged_ && now - last_ < kLogInterval) {
    return;
  }
  tenths_logged_ = std::max(tenths_logged_, tenths);
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = done > 0 ? elapsed * (total_ - done) / done : 0.0;
  fmt::print(stderr, "{} frame {}/{} ({:.0f}%), {:.1f} s elapsed, about {:.0f} s left{}{}\n",
             stage_, done, total_, 100.0 * done / total_, elapsed, left, detail.empty() ? "" : "; ",
             detail);
  std::fflush(stderr);
}

}  // namespace dinam
