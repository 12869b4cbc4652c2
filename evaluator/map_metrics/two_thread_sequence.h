#pragma once

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "evaluator/map_metrics/usable_cores.h"

namespace slamsweep::evaluator::inline map_metrics {

/// Computes make(i) for i = 0 .. count - 1 on the calling thread and one helper thread (each takes
/// the next index not yet taken), and hands every result to use(i, result) on the calling thread
/// in the order of i, as soon as it is there. So a sequence of independent, costly steps (the
/// Harris response of a band) uses both cores while the consumer (the local-maximum search over
/// consecutive bands) still sees them in order. A result waits in memory until its turn; an
/// exception from `make` or `use` is rethrown on the calling thread once the helper has stopped.
/// With one index or one core, everything runs on the calling thread.
template <typename T, typename Make, typename Use>
void ForEachInOrderOnTwoThreads(int count, Make&& make, Use&& use) {
  if (count <= 1 || UsableCores() < 2) {
    for (int i = 0; i < count; ++i) use(i, make(i));
    return;
  }
  std::mutex mutex;
  std::condition_variable ready;
  std::vector<std::optional<T>> results(static_cast<std::size_t>(count));
  std::exception_ptr failure;
  int next_to_make = 0;
  bool stop = false;
  // Takes the next index to compute, or -1 when none is left (or the work was stopped).
  const auto take = [&] {
    std::lock_guard lock(mutex);
    return stop || next_to_make >= count ? -1 : next_to_make++;
  };
  const auto put = [&](int i, std::optional<T> result, std::exception_ptr error) {
    std::lock_guard lock(mutex);
    results[static_cast<std::size_t>(i)] = std::move(result);
    if (error && !failure) failure = error;
    if (error) stop = true;
    ready.notify_all();
  };
  std::thread helper([&] {
    for (int i = take(); i >= 0; i = take()) {
      try {
        put(i, make(i), nullptr);
      } catch (...) {
        put(i, std::nullopt, std::current_exception());
      }
    }
  });
  try {
    for (int i = 0; i < count; ++i) {
      std::unique_lock lock(mutex);
      // Until result i is there: compute another step here rather than wait.
      while (!results[static_cast<std::size_t>(i)] && !failure) {
        if (stop || next_to_make >= count) {
          ready.wait(lock);
          continue;
        }
        const int mine = next_to_make++;
        lock.unlock();
        T made = make(mine);
        lock.lock();
        results[static_cast<std::size_t>(mine)] = std::move(made);
      }
      if (failure) std::rethrow_exception(failure);
      T result = std::move(*results[static_cast<std::size_t>(i)]);
      results[static_cast<std::size_t>(i)].reset();
      lock.unlock();
      use(i, std::move(result));
    }
  } catch (...) {
    {
      std::lock_guard lock(mutex);
      stop = true;
    }
    helper.join();
    throw;
  }
  helper.join();
}

}  // namespace slamsweep::evaluator::inline map_metrics
