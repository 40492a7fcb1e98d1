// (Internal, not installed) f(j) for each block j in [0, blocks), each on a thread of its own (j =
// 0 on the caller's); the first exception of the lowest block that threw is rethrown once all have
// finished (none is left running, none escapes a thread).
#pragma once

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace contensou::detail {

template <class F>
void run_blocks(std::size_t blocks, F&& f) {
  std::vector<std::exception_ptr> errors(blocks);
  const auto run = [&](std::size_t j) {
    try {
      f(j);
    } catch (...) {
      errors[j] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  for (std::size_t j = 1; j < blocks; ++j) workers.emplace_back(run, j);
  if (blocks > 0) run(0);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace contensou::detail
