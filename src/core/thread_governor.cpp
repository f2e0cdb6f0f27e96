#include "core/thread_governor.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "core/machine_load.hpp"
#include "core/thread_team.hpp"

namespace dinam {
namespace {

struct ProcessPolicy {
  std::optional<ThreadChoice> choice;
  LoadMeter meter;
  double stretch_seconds = ThreadGovernor::kStretchSeconds;
};

ProcessPolicy& process_policy() {
  static ProcessPolicy policy;
  return policy;
}

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

LoadMeter machine_load_meter() {
  auto last = std::make_shared<LoadSample>(sample_load());
  const long ticks_per_second = sysconf(_SC_CLK_TCK);
  return [last, ticks_per_second]() -> std::optional<double> {
    const LoadSample now = sample_load();
    const std::optional<double> others = others_busy_cpus(*last, now, ticks_per_second);
    *last = now;
    return others;
  };
}

ThreadCountPolicy::ThreadCountPolicy(int start, int most, int cpus)
    : most_(std::max(1, most)), cpus_(std::max(1, cpus)), settled_(std::clamp(start, 1, most_)) {}

int ThreadCountPolicy::next(const Stretch& stretch) {
  if (trial_) {
    const int tried = *trial_;
    trial_.reset();
    Way& way = tried < settled_ ? down_ : up_;
    if (stretch.seconds_per_step < (1.0 - kMargin) * settled_step_) {
      way = Way{};
      settled_ = tried;
      settled_step_ = stretch.seconds_per_step;
      return settled_;
    }
    way.failures += 1;
    way.wait = std::min(kMostWait, 1 << std::min(way.failures, 6));
    way.others_then = stretch.others_busy.value_or(0.0);
    return settled_;
  }
  settled_step_ = stretch.seconds_per_step;
  if (!stretch.others_busy) {
    return settled_;
  }
  const double others = *stretch.others_busy;
  for (Way* way : {&down_, &up_}) {
    // A load that has moved by a CPU since the last failure is a new machine: try again now.
    if (way->failures > 0 && std::abs(others - way->others_then) >= 1.0) {
      *way = Way{};
    }
    way->wait = std::max(0, way->wait - 1);
  }
  const int room = threads_with_room(others, cpus_, most_);
  if ((room < settled_ && down_.wait == 0) || (room > settled_ && up_.wait == 0)) {
    trial_ = room;
    return room;
  }
  return settled_;
}

ThreadGovernor::ThreadGovernor() {
  const ProcessPolicy& process = process_policy();
  if (process.choice && process.choice->adapts && process.choice->most > 1) {
    policy_.emplace(thread_count(), process.choice->most, process.choice->cpus);
    meter_ = process.meter ? process.meter : machine_load_meter();
    stretch_seconds_ = process.stretch_seconds;
  }
}

void ThreadGovernor::before_run() {
  if (policy_) {
    run_started_ns_ = now_ns();
  }
}

void ThreadGovernor::after_run(std::int64_t steps) {
  if (!policy_ || steps <= 0) {
    return;
  }
  steps_ += steps;
  seconds_ += 1e-9 * static_cast<double>(now_ns() - run_started_ns_);
  if (seconds_ < stretch_seconds_) {
    return;
  }
  const Stretch stretch{thread_count(), seconds_ / static_cast<double>(steps_), meter_()};
  steps_ = 0;
  seconds_ = 0.0;
  const int next = policy_->next(stretch);
  if (next != thread_count()) {
    set_thread_count(next);
    ++changes_;
  }
}

void set_thread_policy(const ThreadChoice& choice, LoadMeter meter, double stretch_seconds) {
  ProcessPolicy& process = process_policy();
  process.choice = choice;
  process.meter = std::move(meter);
  process.stretch_seconds = stretch_seconds;
  set_thread_count(choice.threads);
}

ThreadChoice thread_policy() {
  const ProcessPolicy& process = process_policy();
  if (process.choice) {
    return *process.choice;
  }
  const int threads = thread_count();
  return {threads, threads, false, threads, "set by the program"};
}

}  // namespace dinam
