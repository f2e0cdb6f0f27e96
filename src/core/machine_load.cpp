#include "core/machine_load.hpp"

#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>

#include "core/text_file.hpp"

namespace dinam {
namespace {

std::vector<int> affinity_cpus() {
  std::vector<int> cpus;
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof(mask), &mask) == 0) {
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
      if (CPU_ISSET(cpu, &mask)) {
        cpus.push_back(cpu);
      }
    }
  }
  return cpus;
}

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

std::optional<CpuTicks> cpu_ticks(std::string_view proc_stat, const std::vector<int>& cpus) {
  CpuTicks sum;
  bool found = false;
  while (!proc_stat.empty()) {
    const std::size_t end = std::min(proc_stat.find('\n'), proc_stat.size());
    std::string_view line = proc_stat.substr(0, end);
    proc_stat.remove_prefix(std::min(end + 1, proc_stat.size()));
    if (line.substr(0, 3) != "cpu") {
      continue;
    }
    const std::size_t blank = line.find(' ');
    if (blank == std::string_view::npos) {
      continue;
    }
    const std::string_view name = line.substr(3, blank - 3);
    if (cpus.empty() != name.empty()) {
      continue;  // the summary line for no list, a CPU's own line for a list
    }
    if (!cpus.empty()) {
      int number = -1;
      const auto [at, error] = std::from_chars(name.data(), name.data() + name.size(), number);
      if (error != std::errc() || at != name.data() + name.size() ||
          std::find(cpus.begin(), cpus.end(), number) == cpus.end()) {
        continue;
      }
    }
    // user nice system idle iowait irq softirq steal (guest and guest_nice are within user).
    std::array<std::uint64_t, 8> field{};
    std::string_view rest = line.substr(blank);
    std::size_t read = 0;
    for (; read < field.size(); ++read) {
      const std::size_t start = rest.find_first_not_of(' ');
      if (start == std::string_view::npos) {
        break;
      }
      rest.remove_prefix(start);
      const auto [at, error] = std::from_chars(rest.data(), rest.data() + rest.size(), field[read]);
      if (error != std::errc()) {
        break;
      }
      rest.remove_prefix(static_cast<std::size_t>(at - rest.data()));
    }
    if (read < 5) {
      continue;  // not the kernel's format
    }
    const std::uint64_t idle = field[3] + field[4];
    const std::uint64_t busy = field[0] + field[1] + field[2] + field[5] + field[6] + field[7];
    sum.busy += busy;
    sum.total += busy + idle;
    found = true;
  }
  return found ? std::optional<CpuTicks>(sum) : std::nullopt;
}

LoadSample sample_load() {
  static const std::vector<int> cpus = affinity_cpus();
  LoadSample sample;
  sample.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  sample.own_cpu_seconds = process_cpu_seconds();
  sample.cpus = cpu_ticks(read_text_file("/proc/stat").value_or(""), cpus);
  return sample;
}

std::optional<double> others_busy_cpus(const LoadSample& before, const LoadSample& after,
                                       long ticks_per_second) {
  const double wall = after.wall_seconds - before.wall_seconds;
  if (!before.cpus || !after.cpus || ticks_per_second <= 0 || wall <= 0.0 ||
      after.cpus->total <= before.cpus->total || after.cpus->busy < before.cpus->busy) {
    return std::nullopt;
  }
  const double busy = static_cast<double>(after.cpus->busy - before.cpus->busy) /
                      static_cast<double>(ticks_per_second);
  const double own = after.own_cpu_seconds - before.own_cpu_seconds;
  return std::max(0.0, (busy - own) / wall);
}

std::optional<LoadAverage> parse_load_average(std::string_view text) {
  // "0.52 0.58 0.59 3/1024 12345": three averages, then runnable/all tasks, then the last pid.
  LoadAverage load;
  const auto [after_one, error] =
      std::from_chars(text.data(), text.data() + text.size(), load.one_minute);
  if (error != std::errc()) {
    return std::nullopt;
  }
  std::string_view rest = text.substr(static_cast<std::size_t>(after_one - text.data()));
  for (int skip = 0; skip < 2; ++skip) {  // past the other two averages
    const std::size_t start = rest.find_first_not_of(' ');
    const std::size_t end = rest.find(' ', start == std::string_view::npos ? 0 : start);
    if (start == std::string_view::npos || end == std::string_view::npos) {
      return std::nullopt;
    }
    rest.remove_prefix(end);
  }
  rest.remove_prefix(std::min(rest.find_first_not_of(' '), rest.size()));
  const auto [at, runnable_error] =
      std::from_chars(rest.data(), rest.data() + rest.size(), load.runnable);
  if (runnable_error != std::errc() || at == rest.data() + rest.size() || *at != '/' ||
      load.runnable < 0) {
    return std::nullopt;
  }
  return load;
}

std::optional<RunnableNow> runnable_now() {
  constexpr int kReadings = 5;
  std::vector<int> runnable;
  double average = 0.0;
  for (int k = 0; k < kReadings; ++k) {
    if (k > 0) {
      // Waited out awake: a process that sleeps as it starts is placed again when it wakes, and
      // on a machine as busy as this reading is for, that placement decides whether it shares a
      // core with another process (runs that slept here took 15 % longer beside two busy ones).
      const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(500);
      while (std::chrono::steady_clock::now() < until) {
      }
    }
    const std::optional<LoadAverage> load =
        parse_load_average(read_text_file("/proc/loadavg").value_or(""));
    if (!load) {
      return std::nullopt;
    }
    runnable.push_back(load->runnable);
    average = load->one_minute;
  }
  std::nth_element(runnable.begin(), runnable.begin() + kReadings / 2, runnable.end());
  return RunnableNow{std::max(0, runnable[kReadings / 2] - 1), average};
}

}  // namespace dinam
