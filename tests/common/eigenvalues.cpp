#include "eigenvalues.hpp"

#include <Eigen/Eigenvalues>

namespace contensou::testing {

Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& A) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
}

}  // namespace contensou::testing
