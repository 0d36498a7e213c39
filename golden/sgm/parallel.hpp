// SPDX-License-Identifier: Apache-2.0
// Runs independent jobs on the machine's cores (at most two threads here).
#pragma once

#include <algorithm>
#include <functional>
#include <thread>
#include <vector>

namespace sgm {

inline int workerCount() {
  const unsigned hw = std::thread::hardware_concurrency();
  return std::clamp(int(hw), 1, 2);
}

// Calls body(begin, end) on contiguous slices of [0, n), one per worker.
inline void parallelFor(int n, const std::function<void(int, int)>& body) {
  const int workers = std::min(workerCount(), std::max(n, 1));
  if (workers <= 1) {
    body(0, n);
    return;
  }
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w) {
    const int begin = n * w / workers, end = n * (w + 1) / workers;
    threads.emplace_back(body, begin, end);
  }
  for (std::thread& t : threads) t.join();
}

// Runs the given jobs concurrently and waits for all of them.
inline void runConcurrently(const std::vector<std::function<void()>>& jobs) {
  std::vector<std::thread> threads;
  for (size_t i = 1; i < jobs.size(); ++i) threads.emplace_back(jobs[i]);
  if (!jobs.empty()) jobs[0]();
  for (std::thread& t : threads) t.join();
}

}  // namespace sgm
