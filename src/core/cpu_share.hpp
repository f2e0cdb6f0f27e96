#pragma once
// How many threads to simulate on: the share of the machine this process is given, not every
// core it can see. A Slurm job, a container or `taskset` gives a process part of a machine; more
// threads than that share only wait for each other.
#include <filesystem>
#include <optional>
#include <string>

namespace dinam {

// What the system gives this process, each read where it is said.
struct CpuShare {
  int online_cpus = 1;               // sysconf(_SC_NPROCESSORS_ONLN)
  int affinity_cpus = 1;             // CPUs in the affinity mask (sched_getaffinity; taskset)
  std::optional<double> quota_cpus;  // the tightest cgroup CPU quota on the way to the root, CPUs
  std::string quota_source;          // the file that sets it
  std::optional<int> slurm_cpus;     // SLURM_CPUS_PER_TASK
};

// Reads the share from the system: the affinity mask, the cgroup (v2 `cpu.max`, or v1
// `cpu.cfs_quota_us` over `cpu.cfs_period_us`) of this process and its parents under
// `cgroup_root`, and SLURM_CPUS_PER_TASK.
CpuShare read_cpu_share(const std::filesystem::path& cgroup_root = "/sys/fs/cgroup",
                        const std::filesystem::path& proc_cgroup = "/proc/self/cgroup");

// The CPUs a cgroup's `cpu.max` allows ("150000 100000" is 1.5), or none for "max" or text that
// does not read.
std::optional<double> cpu_max_quota(const std::string& text);

struct ThreadChoice {
  int threads = 1;
  std::string reason;  // "--threads 3", "DINAM_THREADS=4", "2 CPUs: the affinity mask; …"
};

// The thread count: `requested` (--threads) if given, else DINAM_THREADS if set (`dinam_threads`,
// the variable's text; null when unset), else the least of the affinity mask, the cgroup quota
// (rounded up: 1.5 CPUs run 2 threads) and SLURM_CPUS_PER_TASK. Throws UserError for a
// DINAM_THREADS that is not a whole number from 1 up.
ThreadChoice choose_threads(const CpuShare& share, std::optional<int> requested,
                            const char* dinam_threads);

// choose_threads with the system's share and environment.
ThreadChoice choose_threads(std::optional<int> requested);

}  // namespace dinam
