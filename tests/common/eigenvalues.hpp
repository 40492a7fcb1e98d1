// The eigenvalues of a small real matrix (Eigen's EigenSolver), compiled once in
// tests/common/eigenvalues.cpp: instantiated in a test file for each fixed size, the solver
// costs more compile time than the rest of the file (test_landing_gear: 40 s against 27 s under
// ASan).
#pragma once

#include <Eigen/Core>

namespace contensou::testing {

// All eigenvalues of the square matrix A, in Eigen's order.
Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& A);

}  // namespace contensou::testing
