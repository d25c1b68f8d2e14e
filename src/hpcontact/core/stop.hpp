// A request to stop a long computation early — from a signal handler (the command line's SIGTERM
// and SIGINT) or another thread. Newton's method checks it before every iteration and ends as a
// failed solve there, so that a run keeps what had converged (its last-good results) instead of
// being killed with nothing.
#pragma once

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

}  // namespace hpcontact
