#include "serial_kernels.hpp"

#include <cmath>
#include <vector>

namespace contensou::detail {

namespace {

// The serial vector's data and length.
struct View {
  sunrealtype* d;
  sunindextype n;
};
View view(N_Vector v) {
  return {NV_DATA_S(v), NV_LENGTH_S(v)};
}

// w += c u, with nvector_serial.c's cases c = 1 and c = -1 (Vaxpy).
void axpy(sunindextype n, sunrealtype c, const sunrealtype* u, sunrealtype* w) {
  if (c == 1.0) {
    for (sunindextype i = 0; i < n; ++i) w[i] += u[i];
  } else if (c == -1.0) {
    for (sunindextype i = 0; i < n; ++i) w[i] -= u[i];
  } else {
    for (sunindextype i = 0; i < n; ++i) w[i] += c * u[i];
  }
}

// z = v1 + v2 (VSum) and z = v2 - v1 (VDiff).
void sum(sunindextype n, const sunrealtype* v1, const sunrealtype* v2, sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = v1[i] + v2[i];
}
void difference(sunindextype n, const sunrealtype* v1, const sunrealtype* v2, sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = v2[i] - v1[i];
}

// z = c v1 + v2 (VLin1) and z = c v1 - v2 (VLin2).
void lin1(sunindextype n, sunrealtype c, const sunrealtype* v1, const sunrealtype* v2,
          sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = (c * v1[i]) + v2[i];
}
void lin2(sunindextype n, sunrealtype c, const sunrealtype* v1, const sunrealtype* v2,
          sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = (c * v1[i]) - v2[i];
}

// z = c (x + y) (VScaleSum), z = c (x - y) (VScaleDiff) and the general a x + b y.
void scale_sum(sunindextype n, sunrealtype c, const sunrealtype* x, const sunrealtype* y,
               sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = c * (x[i] + y[i]);
}
void scale_difference(sunindextype n, sunrealtype c, const sunrealtype* x, const sunrealtype* y,
                      sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = c * (x[i] - y[i]);
}
void general_sum(sunindextype n, sunrealtype a, const sunrealtype* x, sunrealtype b,
                 const sunrealtype* y, sunrealtype* z) {
  for (sunindextype i = 0; i < n; ++i) z[i] = (a * x[i]) + (b * y[i]);
}

// z = a x + b y with nvector_serial.c's special cases, in its order (each rounds differently:
// c (x + y) is not c x + c y), so that the sums are the library's to the last bit.
void linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* yd = NV_DATA_S(y);
  sunrealtype* zd = NV_DATA_S(z);
  if (b == 1.0 && z == y) return axpy(n, a, xd, yd);
  if (a == 1.0 && z == x) return axpy(n, b, yd, xd);
  if (a == 1.0 && b == 1.0) return sum(n, xd, yd, zd);
  if (a == 1.0 && b == -1.0) return difference(n, yd, xd, zd);  // x - y
  if (a == -1.0 && b == 1.0) return difference(n, xd, yd, zd);  // y - x
  if (a == 1.0) return lin1(n, b, yd, xd, zd);
  if (b == 1.0) return lin1(n, a, xd, yd, zd);
  if (a == -1.0) return lin2(n, b, yd, xd, zd);
  if (b == -1.0) return lin2(n, a, xd, yd, zd);
  if (a == b) return scale_sum(n, a, xd, yd, zd);
  if (a == -b) return scale_difference(n, a, xd, yd, zd);
  general_sum(n, a, xd, b, yd, zd);
}

void constant(sunrealtype c, N_Vector z) {
  const auto [zd, n] = view(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c;
}

void product(N_Vector x, N_Vector y, N_Vector z) {
  const auto [xd, n] = view(x);
  const sunrealtype* yd = NV_DATA_S(y);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] * yd[i];
}

void quotient(N_Vector x, N_Vector y, N_Vector z) {
  const auto [xd, n] = view(x);
  const sunrealtype* yd = NV_DATA_S(y);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] / yd[i];
}

void scale(sunrealtype c, N_Vector x, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* zd = NV_DATA_S(z);
  if (z == x) {
    for (sunindextype i = 0; i < n; ++i) xd[i] *= c;
  } else if (c == 1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i];
  } else if (c == -1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = -xd[i];
  } else {
    for (sunindextype i = 0; i < n; ++i) zd[i] = c * xd[i];
  }
}

void absolute(N_Vector x, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = std::abs(xd[i]);
}

void inverse(N_Vector x, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = 1.0 / xd[i];
}

void add_constant(N_Vector x, sunrealtype b, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + b;
}

// The fused operations, as the generic fallbacks of sundials_nvector.c compose them from the
// operations above (same arithmetic), without a library call per vector.
int linear_combination(int m, sunrealtype* c, N_Vector* X, N_Vector z) {  // z = sum c_i X_i
  scale(c[0], X[0], z);
  for (int i = 1; i < m; ++i) linear_sum(c[i], X[i], 1.0, z, z);
  return 0;
}

int scale_add_multi(int m, sunrealtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  for (int i = 0; i < m; ++i) linear_sum(a[i], x, 1.0, Y[i], Z[i]);  // Z_i = a_i x + Y_i
  return 0;
}

int scale_vector_array(int m, sunrealtype* c, N_Vector* X, N_Vector* Z) {
  for (int i = 0; i < m; ++i) scale(c[i], X[i], Z[i]);
  return 0;
}

sunrealtype dot(N_Vector x, N_Vector y) {
  const auto [xd, n] = view(x);
  const sunrealtype* yd = NV_DATA_S(y);
  sunrealtype sum = 0.0;
  for (sunindextype i = 0; i < n; ++i) sum += xd[i] * yd[i];
  return sum;
}

sunrealtype max_norm(N_Vector x) {
  const auto [xd, n] = view(x);
  sunrealtype max = 0.0;
  for (sunindextype i = 0; i < n; ++i)
    if (std::abs(xd[i]) > max) max = std::abs(xd[i]);
  return max;
}

// sum (x_i w_i)^2, accumulated in index order.
sunrealtype weighted_square_sum(N_Vector x, N_Vector w) {
  const auto [xd, n] = view(x);
  const sunrealtype* wd = NV_DATA_S(w);
  sunrealtype sum = 0.0;
  for (sunindextype i = 0; i < n; ++i) {
    const sunrealtype p = xd[i] * wd[i];
    sum += p * p;
  }
  return sum;
}

// (sum (x_i w_i)^2 / n)^(1/2), the error norm of CVODE's tests.
sunrealtype wrms_norm(N_Vector x, N_Vector w) {
  const sunrealtype mean = weighted_square_sum(x, w) / static_cast<sunrealtype>(NV_LENGTH_S(x));
  return mean <= 0.0 ? 0.0 : std::sqrt(mean);
}

sunrealtype minimum(N_Vector x) {
  const auto [xd, n] = view(x);
  sunrealtype min = xd[0];
  for (sunindextype i = 1; i < n; ++i)
    if (xd[i] < min) min = xd[i];
  return min;
}

void compare(sunrealtype c, N_Vector x, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* zd = NV_DATA_S(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

sunbooleantype inverse_test(N_Vector x, N_Vector z) {
  const auto [xd, n] = view(x);
  sunrealtype* zd = NV_DATA_S(z);
  sunbooleantype no_zero = SUNTRUE;
  for (sunindextype i = 0; i < n; ++i) {
    if (xd[i] == 0.0)
      no_zero = SUNFALSE;
    else
      zd[i] = 1.0 / xd[i];
  }
  return no_zero;
}

// The dense solver's content: the pivots of the last factorisation.
struct DenseContent {
  std::vector<sunindextype> pivots;
  int last_flag = 0;
};
DenseContent& content(SUNLinearSolver S) {
  return *static_cast<DenseContent*>(S->content);
}

SUNLinearSolver_Type solver_type(SUNLinearSolver) {
  return SUNLINEARSOLVER_DIRECT;
}
SUNLinearSolver_ID solver_id(SUNLinearSolver) {
  return SUNLINEARSOLVER_CUSTOM;
}
int solver_initialize(SUNLinearSolver S) {
  content(S).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}
sunindextype solver_last_flag(SUNLinearSolver S) {
  return content(S).last_flag;
}

// LU with partial pivoting of the column-major dense matrix, in place (sundials_dense.c,
// denseGETRF): column k's pivot is its largest entry on or below the diagonal; the multipliers
// a(i,k) / a(k,k) stay below the diagonal. Returns k + 1 for a zero pivot in column k.
int solver_setup(SUNLinearSolver S, SUNMatrix A) {
  sunrealtype** a = SUNDenseMatrix_Cols(A);
  const sunindextype m = SUNDenseMatrix_Rows(A), n = SUNDenseMatrix_Columns(A);
  sunindextype* p = content(S).pivots.data();
  for (sunindextype k = 0; k < n; ++k) {
    sunrealtype* col_k = a[k];
    sunindextype l = k;
    for (sunindextype i = k + 1; i < m; ++i)
      if (std::abs(col_k[i]) > std::abs(col_k[l])) l = i;
    p[k] = l;
    if (col_k[l] == 0.0) {
      content(S).last_flag = static_cast<int>(k + 1);
      return SUNLS_LUFACT_FAIL;
    }
    if (l != k) {
      for (sunindextype i = 0; i < n; ++i) {
        const sunrealtype t = a[i][l];
        a[i][l] = a[i][k];
        a[i][k] = t;
      }
    }
    const sunrealtype mult = 1.0 / col_k[k];
    for (sunindextype i = k + 1; i < m; ++i) col_k[i] *= mult;
    for (sunindextype j = k + 1; j < n; ++j) {
      sunrealtype* col_j = a[j];
      const sunrealtype a_kj = col_j[k];
      if (a_kj != 0.0)
        for (sunindextype i = k + 1; i < m; ++i) col_j[i] -= a_kj * col_k[i];
    }
  }
  content(S).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

// x = A^-1 b from the factors (denseGETRS): permute, L y = b, U x = y.
int solver_solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, sunrealtype) {
  scale(1.0, b, x);
  sunrealtype** a = SUNDenseMatrix_Cols(A);
  const sunindextype n = SUNDenseMatrix_Rows(A);
  const sunindextype* p = content(S).pivots.data();
  sunrealtype* v = NV_DATA_S(x);
  for (sunindextype k = 0; k < n; ++k) {
    if (p[k] != k) {
      const sunrealtype t = v[k];
      v[k] = v[p[k]];
      v[p[k]] = t;
    }
  }
  for (sunindextype k = 0; k < n - 1; ++k) {
    const sunrealtype* col_k = a[k];
    for (sunindextype i = k + 1; i < n; ++i) v[i] -= col_k[i] * v[k];
  }
  for (sunindextype k = n - 1; k > 0; --k) {
    const sunrealtype* col_k = a[k];
    v[k] /= col_k[k];
    for (sunindextype i = 0; i < k; ++i) v[i] -= col_k[i] * v[k];
  }
  v[0] /= a[0][0];
  content(S).last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

int solver_free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete static_cast<DenseContent*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

void use_compiled_vector_ops(N_Vector v) {
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = linear_sum;
  ops->nvconst = constant;
  ops->nvprod = product;
  ops->nvdiv = quotient;
  ops->nvscale = scale;
  ops->nvabs = absolute;
  ops->nvinv = inverse;
  ops->nvaddconst = add_constant;
  ops->nvdotprod = dot;
  ops->nvdotprodlocal = dot;
  ops->nvmaxnorm = max_norm;
  ops->nvmaxnormlocal = max_norm;
  ops->nvwrmsnorm = wrms_norm;
  ops->nvwsqrsumlocal = weighted_square_sum;
  ops->nvmin = minimum;
  ops->nvminlocal = minimum;
  ops->nvcompare = compare;
  ops->nvinvtest = inverse_test;
  ops->nvinvtestlocal = inverse_test;
  ops->nvlinearcombination = linear_combination;
  ops->nvscaleaddmulti = scale_add_multi;
  ops->nvscalevectorarray = scale_vector_array;
}

SUNLinearSolver compiled_dense_solver(N_Vector y, SUNMatrix A, SUNContext ctx) {
  if (SUNMatGetID(A) != SUNMATRIX_DENSE || SUNDenseMatrix_Rows(A) != SUNDenseMatrix_Columns(A) ||
      SUNDenseMatrix_Rows(A) != N_VGetLength(y))
    return nullptr;
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return nullptr;
  S->ops->gettype = solver_type;
  S->ops->getid = solver_id;
  S->ops->initialize = solver_initialize;
  S->ops->setup = solver_setup;
  S->ops->solve = solver_solve;
  S->ops->lastflag = solver_last_flag;
  S->ops->free = solver_free;
  auto* c = new DenseContent;
  c->pivots.resize(static_cast<std::size_t>(SUNDenseMatrix_Rows(A)));
  S->content = c;
  return S;
}

}  // namespace contensou::detail
