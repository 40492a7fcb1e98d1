// Compiled replacements for the serial N_Vector's arithmetic and the dense LU solver of SUNDIALS,
// for the gear's small systems (6 to 11 states). Private to the gear module.
//
// Why: a distribution's SUNDIALS may be built without optimisation (Debian's 6.4.1 is, -O0), and
// then CVODE's vector operations and dense LU on a 6-state system cost more than the model's
// right-hand side. The kernels here are the same algorithms with the same floating-point
// operations in the same order as nvector_serial.c and sundials_dense.c (v6.4), compiled with
// the project's flags, so CVODE's results do not change.
#pragma once

#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace contensou::detail {

// Points the operations of a serial vector at the compiled kernels. Call it before CVodeInit
// (and CVodeSVtolerances): CVODE's own vectors are clones, which copy the operations.
void use_compiled_vector_ops(N_Vector v);

// A direct solver for a dense SUNMatrix (SUNDenseMatrix): LU with partial pivoting in setup,
// the two triangular solves in solve, as SUNLinSol_Dense. Free it with SUNLinSolFree.
SUNLinearSolver compiled_dense_solver(N_Vector y, SUNMatrix A, SUNContext ctx);

}  // namespace contensou::detail
