// Deterministic parallel evaluation of a fit's per-point residual blocks (fit.cpp).
//
// Ceres evaluates the blocks on one thread: with more, it adds the cost and the gradient up per
// thread over chunks that the threads claim as they finish, so the sums' last bits change from
// run to run. Here the first block asked for at a new parameter vector evaluates every block of
// the batch at that vector, split into fixed contiguous ranges over the threads, and the other
// blocks read their result. Each block's numbers come from the same code on the same inputs on
// whatever thread, and Ceres adds them up in its one order: the fit is bit for bit the one-thread
// fit, in about 1 / threads of its time on large data.
#pragma once

#include <ceres/cost_function.h>

#include <memory>
#include <vector>

namespace contensou::detail {

class PointBatch {
 public:
  // Blocks of one parameter block of `parameters` values; `threads` <= 1: evaluated in turn.
  PointBatch(int parameters, int threads) : parameters_(parameters), threads_(threads) {}

  // Takes ownership of `point` (one parameter block of `parameters` values) and returns the
  // cost function to give the problem in its place.
  ceres::CostFunction* add(std::shared_ptr<PointBatch> self, ceres::CostFunction* point);

  // Block i's residuals (and Jacobian, row-major, when `jacobian` is not null) at x.
  bool evaluate(int i, const double* x, double* residuals, double* jacobian);

 private:
  void evaluate_all(const double* x, bool with_jacobians);
  void evaluate_range(std::size_t begin, std::size_t end, bool with_jacobians);

  int parameters_;
  int threads_;
  std::vector<std::unique_ptr<ceres::CostFunction>> points_;
  std::vector<std::size_t> offset_;  // first residual of each block
  std::size_t residuals_ = 0;
  // The cache: every block at x_ (with their Jacobians if has_jacobians_).
  std::vector<double> x_, r_, J_;
  std::vector<char> ok_;
  bool valid_ = false, has_jacobians_ = false;
};

// Threads for a batch of `blocks` points: one per core (at most 8), one per 256 blocks.
int batch_threads(std::size_t blocks);

}  // namespace contensou::detail
