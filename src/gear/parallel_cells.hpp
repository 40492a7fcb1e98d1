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

// The threads a pool really starts for `total` cells: `threads` (0: one per core), at most one
// per core and one per cell, at least one.
inline unsigned usable_threads(unsigned threads, int total) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  if (threads == 0 || threads > cores) threads = cores;
  return std::max(1u, std::min(threads, static_cast<unsigned>(std::max(total, 1))));
}

// Calls cell(k) once for every k in [0, total) on usable_threads(threads, total) threads; cell
// must catch its own exceptions. progress(done, total), if set, ends with (total, total).
inline void run_cells_in_parallel(int total, unsigned threads,
                                  const std::function<void(int, int)>& progress,
                                  const std::function<void(int)>& cell) {
  threads = usable_threads(threads, total);
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
