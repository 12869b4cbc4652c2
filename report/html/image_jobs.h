#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace slamsweep::report::inline html {

/// Calls fn(i) for i in [0, n) on `threads` threads (the calling one among them); fn must only touch
/// data of its own i. Rethrows the first exception once every call ended.
void ParallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& fn);

/// One image to make: `make` runs on a worker thread; `done` runs afterwards on the calling thread.
struct ImageJob {
  std::function<void()> make;
  std::function<void(const std::string& error)> done;  ///< error empty when made
};

/// Runs every job's `make` on `threads` threads, then every `done` in order with the what() of the
/// std::exception its `make` threw ("unknown error" when empty), or an empty string.
void RunImageJobs(std::vector<ImageJob>& jobs, int threads);

}  // namespace slamsweep::report::inline html
