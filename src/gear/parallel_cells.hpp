// Runs independent cells (map cells, Monte Carlo draws) on a pool of threads, the calling
// thread reporting progress every 100 ms while it works too. Private to the gear module.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <thread>
#include <vector>

namespace contensou::detail {

// Calls cell(k) once for every k in [0, total) on `threads` threads (0: one per core); cell
// must catch its own exceptions. progress(done, total), if set, ends with (total, total).
inline void run_cells_in_parallel(int total, unsigned threads,
                                  const std::function<void(int, int)>& progress,
                                  const std::function<void(int)>& cell) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<int> next{0}, done{0};
  auto work = [&] {
    for (int k = next++; k < total; k = next++) {
      cell(k);
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work);
  if (progress) {
    std::thread last(work);
    while (done.load() < total) {
      progress(done.load(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    last.join();
    progress(total, total);
  } else {
    work();
  }
  for (std::thread& t : pool) t.join();
}

}  // namespace contensou::detail
