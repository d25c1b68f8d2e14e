// How much memory this process can still allocate, before a large allocation is tried.
#pragma once

#include <optional>
#include <string>

namespace hpcontact::solve {

/// Bytes this process can still allocate and what limits them (for messages).
struct AvailableMemory {
  double bytes = 0;
  std::string limit;  ///< e.g. "the address-space limit (ulimit -v) of 0.5 GB, 0.1 GB of it in use"
};

/// The least of what is known: the address-space limit (RLIMIT_AS, `ulimit -v`) less the
/// address space in use (/proc/self/statm), the memory limit of the process's control group
/// (cgroup v2 memory.max) less its use, the system's MemAvailable (/proc/meminfo); nullopt where
/// none of them can be read. A snapshot: other processes change the last two.
std::optional<AvailableMemory> available_memory();

}  // namespace hpcontact::solve
