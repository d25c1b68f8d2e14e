// The stop request: one process-wide atomic, lock-free so that a signal handler may set it.
#include "hpcontact/core/stop.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>

namespace hpcontact {

namespace {

/// 0: none; -1: requested without a signal; > 0: requested by that signal.
std::atomic<int> requested{0};
static_assert(std::atomic<int>::is_always_lock_free, "request_stop must be async-signal-safe");

/// How many StoppableWork objects live.
std::atomic<int> armed{0};

}  // namespace

void request_stop(int signal) { requested.store(signal > 0 ? signal : -1); }

bool stop_requested() { return requested.load() != 0; }

int stop_signal() { return std::max(0, requested.load()); }

void clear_stop() { requested.store(0); }

const char* stop_reason() {
  switch (requested.load()) {
    case SIGTERM: return "stopped by SIGTERM";
    case SIGINT: return "stopped by SIGINT";
    case SIGHUP: return "stopped by SIGHUP";
    default: return "stopped on request";
  }
}

Stopped::Stopped(const std::string& doing)
    : Error(std::string(stop_reason()) + " while " + doing), doing_(doing) {}

StoppableWork::StoppableWork() { ++armed; }

StoppableWork::~StoppableWork() { --armed; }

void stop_point(const char* doing) {
  if (requested.load(std::memory_order_relaxed) != 0 && armed.load() > 0) throw Stopped(doing);
}

}  // namespace hpcontact
