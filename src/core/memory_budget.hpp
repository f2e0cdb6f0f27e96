#pragma once
// How much memory this process may still take, from what the system and its cgroup say (and the
// user's own limit): the budget the memory estimate (estimate/memory_estimate.hpp) is held to.
#include <cstdint>
#include <string>

namespace dinam {

// The memory this process may still take, and where the figure came from.
struct MemoryBudget {
  std::uint64_t bytes = 0;
  std::string source;  // e.g. "MemAvailable in /proc/meminfo"
};

// The smallest of: the system's MemAvailable, the cgroup's memory.max less its memory.current
// (a container's or a Slurm job's limit), and $DINAM_MEMORY_LIMIT (bytes, or with a K, M, G or T
// suffix; 0 means no limit). Throws UserError when $DINAM_MEMORY_LIMIT cannot be read. Returns a
// budget of no bytes and an empty source when none can be found.
MemoryBudget available_memory();

}  // namespace dinam
