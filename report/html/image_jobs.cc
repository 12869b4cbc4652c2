#include "report/html/image_jobs.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace slamsweep::report::inline html {

void ParallelFor(std::size_t n, int threads, const std::function<void(std::size_t)>& fn) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 1; t < std::max(threads, 1); ++t) pool.emplace_back(worker);
    worker();
  }
  if (failure) std::rethrow_exception(failure);
}

void RunImageJobs(std::vector<ImageJob>& jobs, int threads) {
  std::vector<std::string> errors(jobs.size());
  ParallelFor(jobs.size(), threads, [&](std::size_t i) {
    try {
      jobs[i].make();
    } catch (const std::exception& error) {
      errors[i] = error.what();
      if (errors[i].empty()) errors[i] = "unknown error";
    }
  });
  for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i].done(errors[i]);
}

}  // namespace slamsweep::report::inline html
