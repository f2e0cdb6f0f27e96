#include "app/command_line.hpp"

namespace dinam {

void add_threads_option(CLI::App& command, std::optional<int>& threads) {
  command
      .add_option("--threads", threads,
                  "Threads to simulate on (default: DINAM_THREADS, else the CPUs this process "
                  "is given: its affinity mask, cgroup quota and SLURM_CPUS_PER_TASK; "
                  "'dinam info' says which); the motion is the same for any count")
      ->check(CLI::Range(1, 4096));
}

}  // namespace dinam
