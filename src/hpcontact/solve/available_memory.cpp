// Available memory from the process's limits and the kernel's figures (Linux).
#include "hpcontact/solve/available_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace hpcontact::solve {

namespace {

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

/// The first number in a file, if it holds one ("max" and missing files give none).
std::optional<double> number_in(const std::string& path) {
  std::ifstream in(path);
  double value;
  if (in >> value) return value;
  return std::nullopt;
}

/// The process's cgroup v2 folder under /sys/fs/cgroup ("0::/path" in /proc/self/cgroup).
std::string cgroup_folder() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("0::", 0) == 0) return "/sys/fs/cgroup" + line.substr(3);
  return "/sys/fs/cgroup";
}

}  // namespace

std::optional<AvailableMemory> available_memory() {
  std::optional<AvailableMemory> least;
  auto take = [&](double bytes, const std::string& limit) {
    bytes = std::max(0.0, bytes);
    if (!least || bytes < least->bytes) least = AvailableMemory{bytes, limit};
  };

  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    // statm's first field: the address space in use (VmSize), in pages.
    const std::optional<double> pages = number_in("/proc/self/statm");
    const double in_use = pages ? *pages * static_cast<double>(sysconf(_SC_PAGESIZE)) : 0.0;
    const double cap = static_cast<double>(limit.rlim_cur);
    take(cap - in_use, "the address-space limit (ulimit -v) of " + gigabytes(cap) + ", " +
                           gigabytes(in_use) + " of it in use");
  }

  const std::string folder = cgroup_folder();
  const std::optional<double> max = number_in(folder + "/memory.max");
  const std::optional<double> current = number_in(folder + "/memory.current");
  if (max && current)
    take(*max - *current, "the control group's memory limit (memory.max) of " + gigabytes(*max) +
                              ", " + gigabytes(*current) + " of it in use");

  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line))
    if (line.rfind("MemAvailable:", 0) == 0) {
      std::istringstream fields(line.substr(13));
      double kilobytes;
      if (fields >> kilobytes) take(1024 * kilobytes, "the memory available (MemAvailable)");
    }
  return least;
}

}  // namespace hpcontact::solve
