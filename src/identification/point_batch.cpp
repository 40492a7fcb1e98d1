#include "point_batch.hpp"

#include <algorithm>
#include <exception>
#include <thread>

#include "run_blocks.hpp"

namespace contensou::detail {
namespace {

// The cost function Ceres sees for block `index`: reads the batch's cache.
class BatchedCost : public ceres::CostFunction {
 public:
  BatchedCost(std::shared_ptr<PointBatch> batch, int index, int residuals, int parameters)
      : batch_(std::move(batch)), index_(index) {
    set_num_residuals(residuals);
    mutable_parameter_block_sizes()->push_back(parameters);
  }
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    return batch_->evaluate(index_, x[0], residuals, jacobians ? jacobians[0] : nullptr);
  }

 private:
  std::shared_ptr<PointBatch> batch_;
  int index_;
};

}  // namespace

int batch_threads(std::size_t blocks) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<int>(
      std::clamp<std::size_t>(blocks / 256, 1, std::min<std::size_t>(cores, 8)));
}

ceres::CostFunction* PointBatch::add(std::shared_ptr<PointBatch> self, ceres::CostFunction* point) {
  const int m = point->num_residuals();
  points_.emplace_back(point);
  offset_.push_back(residuals_);
  residuals_ += static_cast<std::size_t>(m);
  valid_ = false;
  return new BatchedCost(std::move(self), static_cast<int>(points_.size() - 1), m, parameters_);
}

bool PointBatch::evaluate(int i, const double* x, double* residuals, double* jacobian) {
  // The same request as the cache's (x and whether with Jacobians: automatic differentiation's
  // residuals may differ in the last bits from the plain evaluation's), or all blocks again.
  const bool same =
      valid_ && has_jacobians_ == (jacobian != nullptr) && std::equal(x_.begin(), x_.end(), x);
  if (!same) evaluate_all(x, jacobian != nullptr);
  const std::size_t k = static_cast<std::size_t>(i);
  if (!ok_[k]) return false;
  const std::size_t m = static_cast<std::size_t>(points_[k]->num_residuals());
  const std::size_t n = static_cast<std::size_t>(parameters_);
  std::copy_n(r_.begin() + static_cast<std::ptrdiff_t>(offset_[k]), m, residuals);
  if (jacobian)
    std::copy_n(J_.begin() + static_cast<std::ptrdiff_t>(offset_[k] * n), m * n, jacobian);
  return true;
}

void PointBatch::evaluate_range(std::size_t begin, std::size_t end, bool with_jacobians) {
  const std::size_t n = static_cast<std::size_t>(parameters_);
  const double* x = x_.data();
  for (std::size_t k = begin; k < end; ++k) {
    double* J = with_jacobians ? J_.data() + offset_[k] * n : nullptr;
    ok_[k] = points_[k]->Evaluate(&x, r_.data() + offset_[k], with_jacobians ? &J : nullptr);
  }
}

void PointBatch::evaluate_all(const double* x, bool with_jacobians) {
  valid_ = false;
  x_.assign(x, x + parameters_);
  r_.resize(residuals_);
  if (with_jacobians) J_.resize(residuals_ * static_cast<std::size_t>(parameters_));
  ok_.assign(points_.size(), 0);
  const std::size_t blocks = points_.size();
  const std::size_t t = static_cast<std::size_t>(std::max(1, threads_));
  run_blocks(t, [&](std::size_t j) {
    evaluate_range(blocks * j / t, blocks * (j + 1) / t, with_jacobians);
  });
  valid_ = true;
  has_jacobians_ = with_jacobians;
}

}  // namespace contensou::detail
