#pragma once
// What the rest of the machine is doing to the CPUs this process may use: how many of them other
// work keeps busy, now and over a stretch of the run. The thread count follows it
// (core/thread_governor.hpp): a team larger than the CPUs left free waits at every meeting for a
// member whose core another process holds, and on a machine as shared as a CI runner that costs
// more than the team gains (bench/notes/threads.md, "Threads under load").
//
// Two readings, for two moments:
// - at the start, before this process has done anything, the tasks the kernel counts as runnable
//   now (/proc/loadavg's fourth field), sampled a few times over a few milliseconds: exact at
//   once, where the load average lags a minute behind a process that has just started;
// - during a run, the busy time of the CPUs in this process's affinity mask (/proc/stat, steal
//   included) less this process's own CPU time, over the stretch: the CPUs the others took.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dinam {

// Busy and total time of a set of CPUs, in the kernel's clock ticks (USER_HZ).
struct CpuTicks {
  std::uint64_t busy = 0;   // user, nice, system, irq, softirq and steal
  std::uint64_t total = 0;  // busy, idle and iowait
};

// The ticks of the CPUs numbered in `cpus`, read from the text of /proc/stat; none when no line
// of theirs reads (an empty `cpus` reads the machine's summary line).
std::optional<CpuTicks> cpu_ticks(std::string_view proc_stat, const std::vector<int>& cpus);

// One reading of the load, to be set against a later one.
struct LoadSample {
  double wall_seconds = 0.0;     // on the steady clock
  double own_cpu_seconds = 0.0;  // this process's CPU time, all its threads
  std::optional<CpuTicks> cpus;  // those of the affinity mask
};

// Reads the load now, over the CPUs of this process's affinity mask.
LoadSample sample_load();

// The CPUs that other work kept busy between two readings: their busy time less this process's
// own, over the wall time between. None where /proc/stat did not read or no tick passed.
std::optional<double> others_busy_cpus(const LoadSample& before, const LoadSample& after,
                                       long ticks_per_second);

// /proc/loadavg: the one-minute load average and the tasks runnable now (this one among them).
struct LoadAverage {
  double one_minute = 0.0;
  int runnable = 0;
};
std::optional<LoadAverage> parse_load_average(std::string_view text);

// The tasks other than this process that are runnable now, on the whole machine: the median of
// a few readings of /proc/loadavg half a millisecond apart (one reading may fall in a busy
// process's brief sleep), less this process's reading thread. With the one-minute average beside
// it.
struct RunnableNow {
  int others = 0;
  double load_average = 0.0;
};
std::optional<RunnableNow> runnable_now();

}  // namespace dinam
