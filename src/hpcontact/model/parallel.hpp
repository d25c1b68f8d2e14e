// Loops over elements run in parallel (OpenMP), whose exceptions reach the caller as the
// errors they are instead of ending the process.
#pragma once

#include <atomic>
#include <exception>

#include "hpcontact/core/stop.hpp"

namespace hpcontact::model {

/// Calls body(i) for every i in [0, n), in parallel (dynamic schedule), with a stop point
/// (core/stop.hpp: "assembling") before each call. An exception thrown by a call leaves the
/// region (which would std::terminate the process) only as a captured std::exception_ptr,
/// rethrown after the loop: that of the smallest i that threw, so the error does not depend on
/// the threads' timing. Calls of larger i not yet started are skipped.
template <class Body>
void parallel_for(int n, const Body& body) {
  std::exception_ptr error;
  std::atomic<int> first_error{n};
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < n; ++i) {
    if (i > first_error.load(std::memory_order_relaxed)) continue;
    try {
      stop_point("assembling");
      body(i);
    } catch (...) {
#pragma omp critical(hpcontact_parallel_for_error)
      if (i < first_error.load()) {
        error = std::current_exception();
        first_error.store(i);
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace hpcontact::model
