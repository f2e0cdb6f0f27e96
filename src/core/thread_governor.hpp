#pragma once
// A thread count that follows the machine as it is now. The motion does not depend on the count
// (bench/notes/threads.md), so a run may change it between any two runs of steps; this decides
// when. Each stretch of runs (a tenth of a second or more) it reads how many of the process's
// CPUs other work kept busy (core/machine_load.hpp). Where that leaves room for fewer threads
// than the team has, or for more, it tries that count for one stretch and keeps it if a step
// went faster, else goes back and waits ever longer (doubling, up to about six seconds) before
// trying that way again, unless the load moves by a CPU meanwhile.
//
// Why trials, not the load alone: the load says where a change might pay, not that it does (a
// team of two on a core and a half may still beat one thread, a model may share badly). Why the
// load, not trials alone: on an idle machine the time of a stretch varies by tens of per cent
// from one to the next, and a run that tried other counts on that noise lost 10 to 20 % there
// (tried in issue 29); on an idle machine the load asks for nothing, so nothing is tried.
#include <cstdint>
#include <functional>
#include <optional>

#include "core/cpu_share.hpp"

namespace dinam {

// The CPUs other work kept busy since the meter was last read; none where it cannot tell.
using LoadMeter = std::function<std::optional<double>()>;

// A meter of the machine (core/machine_load.hpp's samples, from its first reading on).
LoadMeter machine_load_meter();

// What one stretch at a count measured.
struct Stretch {
  int threads = 1;
  double seconds_per_step = 0.0;
  std::optional<double> others_busy;  // CPUs
};

// The decisions alone, with no clock: each stretch's figures in, the next stretch's count out.
class ThreadCountPolicy {
 public:
  // Counts from 1 to `most`, on a machine of which this process may run on `cpus`.
  ThreadCountPolicy(int start, int most, int cpus);

  // The count for the next stretch, given the one just measured.
  int next(const Stretch& stretch);

  int settled() const { return settled_; }
  bool trying() const { return trial_.has_value(); }

  // A trial keeps its count when its step is this much faster than the step before it.
  static constexpr double kMargin = 0.03;
  // The longest wait after failed trials, in stretches.
  static constexpr int kMostWait = 64;

 private:
  struct Way {
    int failures = 0;
    int wait = 0;              // stretches before the next trial this way
    double others_then = 0.0;  // the load at the last failure
  };

  int most_;
  int cpus_;
  int settled_;
  std::optional<int> trial_;
  double settled_step_ = 0.0;  // the settled count's step, the stretch before a trial
  Way down_;
  Way up_;
};

// The process's thread count during a run, and its stretches: `before_run` starts the clock on a
// run of steps, `after_run` stops it and, at the end of a stretch, sets the count for the next.
// Does nothing for a fixed count (--threads, DINAM_THREADS, a policy never set: tests and
// benchmarks set the count themselves).
class ThreadGovernor {
 public:
  ThreadGovernor();
  void before_run();
  void after_run(std::int64_t steps);
  // Times the count changed in this run.
  int changes() const { return changes_; }

  // A stretch lasts at least this long (s): long enough to read the load from the kernel's
  // 10 ms ticks to a tenth of a CPU on two CPUs, short enough to leave a bad count soon.
  static constexpr double kStretchSeconds = 0.1;

 private:
  std::optional<ThreadCountPolicy> policy_;
  LoadMeter meter_;
  double stretch_seconds_ = kStretchSeconds;
  int changes_ = 0;
  std::int64_t steps_ = 0;
  double seconds_ = 0.0;
  std::int64_t run_started_ns_ = 0;
};

// How the process chooses its thread count (main, from choose_threads): sets the count to start
// with; a run then adapts it where `choice.adapts`, reading `meter` (the machine's when empty)
// each stretch of `stretch_seconds` (0: every run of steps, as tests ask).
void set_thread_policy(const ThreadChoice& choice, LoadMeter meter = {},
                       double stretch_seconds = ThreadGovernor::kStretchSeconds);
// The choice set last; a fixed one of the team's count before any.
ThreadChoice thread_policy();

}  // namespace dinam
