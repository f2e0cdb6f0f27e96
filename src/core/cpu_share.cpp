#include "core/cpu_share.hpp"

#include <fmt/format.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "core/text_file.hpp"

namespace dinam {
namespace {

// A whole number from 1 up that is the whole of `text` (surrounding blanks aside).
std::optional<long long> positive_whole(std::string text) {
  const auto first = text.find_first_not_of(" \t\n");
  const auto last = text.find_last_not_of(" \t\n");
  if (first == std::string::npos) {
    return std::nullopt;
  }
  text = text.substr(first, last - first + 1);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1) {
    return std::nullopt;
  }
  return value;
}

// v1: the quota over the period, where a quota is set (-1 is none).
std::optional<double> cfs_quota(const std::filesystem::path& folder) {
  const std::optional<std::string> quota = read_text_file(folder / "cpu.cfs_quota_us");
  const std::optional<std::string> period = read_text_file(folder / "cpu.cfs_period_us");
  if (!quota || !period) {
    return std::nullopt;
  }
  const std::optional<long long> q = positive_whole(*quota);
  const std::optional<long long> p = positive_whole(*period);
  if (!q || !p) {
    return std::nullopt;
  }
  return static_cast<double>(*q) / static_cast<double>(*p);
}

// The folders of a cgroup and of its parents up to the hierarchy's root, under `mount`.
std::vector<std::filesystem::path> cgroup_and_parents(const std::filesystem::path& mount,
                                                      const std::string& path) {
  std::vector<std::filesystem::path> folders;
  std::filesystem::path relative = std::filesystem::path(path).relative_path();
  for (;;) {
    folders.push_back(mount / relative);
    if (relative.empty()) {
      break;
    }
    relative = relative.parent_path();
  }
  return folders;
}

struct Quota {
  std::optional<double> cpus;
  std::string source;
};

void tighten(Quota& quota, std::optional<double> cpus, const std::filesystem::path& file) {
  if (cpus && (!quota.cpus || *cpus < *quota.cpus)) {
    quota.cpus = cpus;
    quota.source = file.string();
  }
}

// The tightest quota of the process's cgroups (v2, and v1's cpu controller).
Quota read_quota(const std::filesystem::path& root, const std::filesystem::path& proc_cgroup) {
  Quota quota;
  const std::optional<std::string> listing = read_text_file(proc_cgroup);
  if (!listing) {
    return quota;
  }
  std::istringstream lines(*listing);
  std::string line;
  while (std::getline(lines, line)) {
    // "hierarchy-id:controllers:path"; v2 is "0::path".
    const auto first = line.find(':');
    const auto second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) {
      continue;
    }
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    if (controllers.empty()) {
      for (const std::filesystem::path& folder : cgroup_and_parents(root, path)) {
        const std::optional<std::string> text = read_text_file(folder / "cpu.max");
        tighten(quota, text ? cpu_max_quota(*text) : std::nullopt, folder / "cpu.max");
      }
      continue;
    }
    std::istringstream names(controllers);
    std::string name;
    bool cpu = false;
    while (std::getline(names, name, ',')) {
      cpu = cpu || name == "cpu";
    }
    if (!cpu) {
      continue;
    }
    for (const char* mount : {"cpu,cpuacct", "cpu", "cpuacct,cpu"}) {
      for (const std::filesystem::path& folder : cgroup_and_parents(root / mount, path)) {
        tighten(quota, cfs_quota(folder), folder / "cpu.cfs_quota_us");
      }
    }
  }
  return quota;
}

}  // namespace

std::optional<double> cpu_max_quota(const std::string& text) {
  std::istringstream in(text);
  std::string quota;
  std::string period;
  if (!(in >> quota >> period)) {
    return std::nullopt;
  }
  const std::optional<long long> q = positive_whole(quota);
  const std::optional<long long> p = positive_whole(period);
  if (!q || !p) {
    return std::nullopt;  // "max": no quota
  }
  return static_cast<double>(*q) / static_cast<double>(*p);
}

std::optional<double> throttled_share(const std::string& cpu_stat) {
  std::istringstream lines(cpu_stat);
  std::string key;
  long long value = 0;
  std::optional<long long> periods;
  std::optional<long long> throttled;
  while (lines >> key >> value) {
    if (key == "nr_periods") {
      periods = value;
    } else if (key == "nr_throttled") {
      throttled = value;
    }
  }
  if (!periods || !throttled || *periods <= 0 || *throttled < 0) {
    return std::nullopt;
  }
  return std::min(1.0, static_cast<double>(*throttled) / static_cast<double>(*periods));
}

CpuShare read_cpu_share(const std::filesystem::path& cgroup_root,
                        const std::filesystem::path& proc_cgroup) {
  CpuShare share;
  share.online_cpus = std::max(1, static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)));
  share.affinity_cpus = share.online_cpus;
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof(mask), &mask) == 0) {
    share.affinity_cpus = std::max(1, CPU_COUNT(&mask));
  }
  const Quota quota = read_quota(cgroup_root, proc_cgroup);
  share.quota_cpus = quota.cpus;
  share.quota_source = quota.source;
  if (quota.cpus) {
    // v2 and v1 alike keep nr_periods and nr_throttled in cpu.stat beside the quota.
    const std::optional<std::string> stat =
        read_text_file(std::filesystem::path(quota.source).parent_path() / "cpu.stat");
    share.throttled_share = stat ? throttled_share(*stat) : std::nullopt;
  }
  if (const char* slurm = std::getenv("SLURM_CPUS_PER_TASK")) {
    if (const std::optional<long long> cpus = positive_whole(slurm)) {
      share.slurm_cpus = static_cast<int>(std::min<long long>(*cpus, 1 << 20));
    }
  }
  return share;
}

int threads_with_room(double others_busy, int cpus, int most) {
  const double free = static_cast<double>(cpus) - others_busy;
  return std::clamp(static_cast<int>(std::floor(free + 0.5)), 1, std::max(1, most));
}

ThreadChoice choose_threads(const CpuShare& share, std::optional<int> requested,
                            const char* dinam_threads, const std::optional<RunnableNow>& now) {
  if (requested) {
    const int threads = std::max(1, *requested);
    return {threads, threads, false, threads, fmt::format("--threads {}", *requested)};
  }
  if (dinam_threads != nullptr) {
    const std::optional<long long> threads = positive_whole(dinam_threads);
    if (!threads || *threads > 4096) {
      throw_user_error({},
                       "DINAM_THREADS is '{}', not a thread count; give a whole number from 1 "
                       "to 4096 (e.g. DINAM_THREADS=2), or unset it to use the CPUs this process "
                       "is given",
                       dinam_threads);
    }
    const int fixed = static_cast<int>(*threads);
    return {fixed, fixed, false, fixed, fmt::format("DINAM_THREADS={}", *threads)};
  }
  int most = share.affinity_cpus;
  std::string reason = fmt::format("{} of the machine's {} CPUs in the affinity mask",
                                   share.affinity_cpus, share.online_cpus);
  if (share.quota_cpus) {
    const bool throttled = share.throttled_share && *share.throttled_share > kThrottledShare;
    const double cpus =
        throttled ? std::floor(*share.quota_cpus + 1e-9) : std::ceil(*share.quota_cpus - 1e-9);
    reason +=
        fmt::format("; a cgroup quota of {:.3g} CPUs ({})", *share.quota_cpus, share.quota_source);
    if (throttled) {
      reason += fmt::format(", throttled in {:.0f} % of its periods", 100 * *share.throttled_share);
    }
    most = std::min(most, std::max(1, static_cast<int>(cpus)));
  } else {
    reason += "; no cgroup CPU quota";
  }
  if (share.slurm_cpus) {
    reason += fmt::format("; SLURM_CPUS_PER_TASK={}", *share.slurm_cpus);
    most = std::min(most, *share.slurm_cpus);
  }
  most = std::max(1, most);
  int threads = most;
  if (now) {
    // The runnable tasks are the whole machine's; those on this process's CPUs are their share.
    const double others = now->others * static_cast<double>(share.affinity_cpus) /
                          static_cast<double>(std::max(share.online_cpus, share.affinity_cpus));
    threads = threads_with_room(others, share.affinity_cpus, most);
    reason += fmt::format(
        "; {} other task{} runnable now (load average {:.2f}), {}", now->others,
        now->others == 1 ? "" : "s", now->load_average,
        threads < most ? fmt::format("so {} of {}", threads, most) : std::string("room for all"));
  }
  if (most > 1) {
    reason += "; the run changes it whenever another count is faster";
  }
  return {threads, most, true, share.affinity_cpus, reason};
}

ThreadChoice choose_threads(std::optional<int> requested) {
  const char* variable = std::getenv("DINAM_THREADS");
  if (requested || variable != nullptr) {
    return choose_threads(read_cpu_share(), requested, variable);
  }
  return choose_threads(read_cpu_share(), requested, variable, runnable_now());
}

}  // namespace dinam
