#pragma once
// A request to stop, made by SIGINT or SIGTERM (app/command_support.hpp installs the handlers)
// and honoured by every loop that can run for long: the steps, Newton's iterations, the settle,
// the natural modes, the wait for a mesh import, the movie encoding. Each calls stop_if_asked()
// at a point where unwinding leaves nothing half made (never inside a parallel region: an
// exception must not leave an OpenMP or thread-team worker).
//
// The request is never cleared once made: a signal that lands between two loops, or between two
// commands' scopes, still stops the next check (a cleared flag was how a signal could be lost).
#include <stdexcept>
#include <string>

namespace dinam {

// Thrown by stop_if_asked(), so that the command unwinds and its destructors remove what it had
// not finished (a temporary cache folder, a partial movie, ffmpeg itself).
class Interrupted : public std::runtime_error {
 public:
  // `outcome` says what was kept and what was not made; a generic sentence without it.
  explicit Interrupted(int signal, const std::string& outcome = "");
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Records that `signal` asked to stop (the first one is kept). Async-signal-safe: a lock-free
// atomic store, nothing else.
void request_stop(int signal) noexcept;

// The signal that asked to stop, or 0. Cheap enough for any loop (one relaxed atomic load).
int stop_signal() noexcept;

// Throws Interrupted when a signal has asked to stop.
void stop_if_asked();

}  // namespace dinam
