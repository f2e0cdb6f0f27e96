#pragma once
// How many threads to simulate on: the share of the machine this process is given, not every
// core it can see, less what other work is keeping busy as it starts. A Slurm job, a container or
// `taskset` gives a process part of a machine, and other processes take some of what is left;
// more threads than that only wait for each other. A run then follows the machine as it changes
// (core/thread_governor.hpp), within the share.
#include <filesystem>
#include <optional>
#include <string>

#include "core/machine_load.hpp"

namespace dinam {

// What the system gives this process, each read where it is said.
struct CpuShare {
  int online_cpus = 1;               // sysconf(_SC_NPROCESSORS_ONLN)
  int affinity_cpus = 1;             // CPUs in the affinity mask (sched_getaffinity; taskset)
  std::optional<double> quota_cpus;  // the tightest cgroup CPU quota on the way to the root, CPUs
  std::string quota_source;          // the file that sets it
  std::optional<int> slurm_cpus;     // SLURM_CPUS_PER_TASK
  // The share of the quota's periods in which the cgroup was throttled (its cpu.stat's
  // nr_throttled over nr_periods): how often the group as a whole hits its quota.
  std::optional<double> throttled_share;
};

// A cgroup's cpu.stat text: nr_throttled over nr_periods, none before the first period.
std::optional<double> throttled_share(const std::string& cpu_stat);

// Reads the share from the system: the affinity mask, the cgroup (v2 `cpu.max`, or v1
// `cpu.cfs_quota_us` over `cpu.cfs_period_us`) of this process and its parents under
// `cgroup_root`, and SLURM_CPUS_PER_TASK.
CpuShare read_cpu_share(const std::filesystem::path& cgroup_root = "/sys/fs/cgroup",
                        const std::filesystem::path& proc_cgroup = "/proc/self/cgroup");

// The CPUs a cgroup's `cpu.max` allows ("150000 100000" is 1.5), or none for "max" or text that
// does not read.
std::optional<double> cpu_max_quota(const std::string& text);

struct ThreadChoice {
  int threads = 1;      // to start with
  int most = 1;         // the share: what a run that adapts may go up to
  bool adapts = false;  // whether the run follows the machine (not with --threads, DINAM_THREADS)
  int cpus = 1;         // the CPUs of the affinity mask, on which the others' load is read
  std::string reason;   // "--threads 3", "DINAM_THREADS=4", "2 CPUs: the affinity mask; …"
};

// Of the share's threads, a quota throttled in more than this share of its periods counts whole
// CPUs only (1.5 CPUs run 1 thread): the group is already using all of it.
inline constexpr double kThrottledShare = 0.2;

// The threads the load leaves room for on `cpus` CPUs of which others keep `others_busy` busy:
// the CPUs left free, rounded, within [1, most]. The start and the run (core/thread_governor.hpp)
// both count so.
int threads_with_room(double others_busy, int cpus, int most);

// The thread count: `requested` (--threads) if given, else DINAM_THREADS if set (`dinam_threads`,
// the variable's text; null when unset), both fixed for the run; else the share — the least of
// the affinity mask, the cgroup quota (rounded up: 1.5 CPUs run 2 threads, unless the group is
// throttled often) and SLURM_CPUS_PER_TASK — less the CPUs that the tasks runnable now (`now`,
// spread evenly over the machine's CPUs) leave no room on, at least 1; a run adapts it within
// the share. Throws UserError for a DINAM_THREADS that is not a whole number from 1 up.
ThreadChoice choose_threads(const CpuShare& share, std::optional<int> requested,
                            const char* dinam_threads,
                            const std::optional<RunnableNow>& now = std::nullopt);

// choose_threads with the system's share, load and environment.
ThreadChoice choose_threads(std::optional<int> requested);

}  // namespace dinam
