// A request to stop a long computation early — from a signal handler (the command line's SIGTERM,
// SIGINT and SIGHUP) or another thread. Newton's method checks it before every iteration, and
// stop points inside the work of an iteration (assembly, between a factorisation's phases)
// abandon that work, so that a run stops within a moment and keeps what had converged (its
// last-good results) instead of being killed with nothing.
#pragma once

#include <string>

#include "hpcontact/core/error.hpp"

namespace hpcontact {

/// Asks every solve of the process to stop; `signal` (> 0) is the signal that asked, for the
/// messages. Async-signal-safe (one lock-free atomic store).
void request_stop(int signal = 0);

/// Whether a stop has been requested (and not cleared).
bool stop_requested();

/// The signal given to request_stop, 0 if none was or no stop is requested.
int stop_signal();

/// Forgets the request (a caller that handled it and goes on).
void clear_stop();

/// "stopped on request" or "stopped by SIGTERM" (the signal's name): what a solve it ended says.
const char* stop_reason();

/// What a stop point throws: the work it was in is abandoned, its results incomplete. what():
/// "stopped by SIGTERM while <doing>".
class Stopped : public Error {
public:
  explicit Stopped(const std::string& doing);
  /// What was abandoned: "assembling", "factorising", ...
  const std::string& doing() const { return doing_; }

private:
  std::string doing_;
};

/// While one lives (in any thread), stop points throw Stopped once a stop is requested. Work
/// whose caller can give it up is armed so — a Newton solve (which ends as stopped, keeping the
/// last iterate), the assembly of a system to solve — and the work that keeps a stopped run's
/// results (writing last-good/) is not: its stop points do nothing.
class StoppableWork {
public:
  StoppableWork();
  ~StoppableWork();
  StoppableWork(const StoppableWork&) = delete;
  StoppableWork& operator=(const StoppableWork&) = delete;
};

/// Throws Stopped(doing) if a stop is requested while some StoppableWork lives; two atomic
/// loads otherwise. Call it between pieces of work of a fraction of a second at most (an
/// element, a block of an element's quadrature points, a phase of a factorisation), so that a
/// stop takes effect within a moment at any size. Safe in OpenMP threads (model::parallel_for
/// carries the exception out of its loop).
void stop_point(const char* doing);

}  // namespace hpcontact
