#include "core/stop_request.hpp"

#include <fmt/format.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace dinam {
namespace {

// Written by a signal handler on whichever thread the signal lands, read by every thread.
std::atomic<int> stop_signal_received{0};
static_assert(std::atomic<int>::is_always_lock_free,
              "a signal handler may only use lock-free atomics");

std::string signal_name(int signal) {
  if (signal == SIGINT) {
    return "SIGINT";
  }
  if (signal == SIGTERM) {
    return "SIGTERM";
  }
  return strsignal(signal);
}

}  // namespace

Interrupted::Interrupted(int signal, const std::string& outcome)
    : std::runtime_error(fmt::format(
          "stopped by {}: {}", signal_name(signal),
          outcome.empty() ? "finished files are kept, unfinished ones removed" : outcome)),
      signal_(signal) {}

void request_stop(int signal) noexcept {
  int none = 0;
  stop_signal_received.compare_exchange_strong(none, signal, std::memory_order_relaxed);
}

int stop_signal() noexcept {
  return stop_signal_received.load(std::memory_order_relaxed);
}

void stop_if_asked() {
  if (const int signal = stop_signal(); signal != 0) {
    throw Interrupted(signal);
  }
}

}  // namespace dinam
