// The compiled replacements of SUNDIALS' serial vector operations and dense LU
// (src/gear/serial_kernels.hpp) give SUNDIALS' own results to the last bit, on the gear's sizes
// and on the special cases of the linear sum (a, b = +-1, a = +-b, z aliasing x or y).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <sunlinsol/sunlinsol_dense.h>
#include "serial_kernels.hpp"

namespace {

struct Context {
  SUNContext ctx = nullptr;
  Context() { SUNContext_Create(nullptr, &ctx); }
  ~Context() { SUNContext_Free(&ctx); }
};

// A pair of vectors with the same entries: one with SUNDIALS' operations, one with ours.
struct Pair {
  N_Vector ref, ours;
  Pair(sunindextype n, SUNContext ctx, std::mt19937& rng)
      : ref(N_VNew_Serial(n, ctx)), ours(N_VNew_Serial(n, ctx)) {
    contensou::detail::use_compiled_vector_ops(ours);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (sunindextype i = 0; i < n; ++i) NV_Ith_S(ref, i) = NV_Ith_S(ours, i) = u(rng) / 7.0;
  }
  ~Pair() {
    N_VDestroy(ref);
    N_VDestroy(ours);
  }
  Pair(const Pair&) = delete;
  Pair& operator=(const Pair&) = delete;
};

bool same_bits(N_Vector a, N_Vector b) {
  return NV_LENGTH_S(a) == NV_LENGTH_S(b) &&
         std::memcmp(NV_DATA_S(a), NV_DATA_S(b),
                     sizeof(sunrealtype) * static_cast<std::size_t>(NV_LENGTH_S(a))) == 0;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST(SerialKernels, VectorOperationsMatchSundialsBitForBit) {
  Context c;
  std::mt19937 rng(7);
  const std::vector<double> coefficients{1.0, -1.0, 0.37, -0.37, 2.5, 0.0};
  for (sunindextype n : {6, 8, 9, 11}) {
    Pair x(n, c.ctx, rng), y(n, c.ctx, rng), z(n, c.ctx, rng), w(n, c.ctx, rng);
    for (sunindextype i = 0; i < n; ++i)
      NV_Ith_S(w.ref, i) = NV_Ith_S(w.ours, i) = 0.5 + static_cast<double>(i);
    for (double a : coefficients) {
      for (double b : coefficients) {
        // z = a x + b y, and in place on x and on y.
        N_VLinearSum(a, x.ref, b, y.ref, z.ref);
        N_VLinearSum(a, x.ours, b, y.ours, z.ours);
        EXPECT_TRUE(same_bits(z.ref, z.ours)) << a << " " << b;
        N_VLinearSum(a, x.ref, b, z.ref, z.ref);
        N_VLinearSum(a, x.ours, b, z.ours, z.ours);
        EXPECT_TRUE(same_bits(z.ref, z.ours)) << a << " " << b << " z = y";
        N_VLinearSum(a, z.ref, b, y.ref, z.ref);
        N_VLinearSum(a, z.ours, b, y.ours, z.ours);
        EXPECT_TRUE(same_bits(z.ref, z.ours)) << a << " " << b << " z = x";
      }
      N_VScale(a, x.ref, z.ref);
      N_VScale(a, x.ours, z.ours);
      EXPECT_TRUE(same_bits(z.ref, z.ours));
      N_VScale(a, z.ref, z.ref);
      N_VScale(a, z.ours, z.ours);
      EXPECT_TRUE(same_bits(z.ref, z.ours));
      N_VAddConst(x.ref, a, z.ref);
      N_VAddConst(x.ours, a, z.ours);
      EXPECT_TRUE(same_bits(z.ref, z.ours));
      N_VCompare(std::abs(a) / 10.0, x.ref, z.ref);
      N_VCompare(std::abs(a) / 10.0, x.ours, z.ours);
      EXPECT_TRUE(same_bits(z.ref, z.ours));
    }
    // Fused operations against their generic compositions (SUNDIALS' fallback when absent).
    std::vector<double> cs{0.3, 1.0, -1.0, 2.0};
    std::vector<N_Vector> Xr{x.ref, y.ref, w.ref, x.ref}, Xo{x.ours, y.ours, w.ours, x.ours};
    N_VLinearCombination(4, cs.data(), Xr.data(), z.ref);
    N_VLinearCombination(4, cs.data(), Xo.data(), z.ours);
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    std::vector<N_Vector> Yr{y.ref, z.ref}, Yo{y.ours, z.ours};
    N_VScaleAddMulti(2, cs.data(), x.ref, Yr.data(), Yr.data());
    N_VScaleAddMulti(2, cs.data(), x.ours, Yo.data(), Yo.data());
    EXPECT_TRUE(same_bits(y.ref, y.ours));
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    N_VProd(x.ref, y.ref, z.ref);
    N_VProd(x.ours, y.ours, z.ours);
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    N_VDiv(x.ref, w.ref, z.ref);
    N_VDiv(x.ours, w.ours, z.ours);
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    N_VAbs(x.ref, z.ref);
    N_VAbs(x.ours, z.ours);
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    N_VInv(w.ref, z.ref);
    N_VInv(w.ours, z.ours);
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    EXPECT_EQ(N_VInvTest(x.ref, z.ref), N_VInvTest(x.ours, z.ours));
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    N_VConst(0.1, z.ref);
    N_VConst(0.1, z.ours);
    EXPECT_TRUE(same_bits(z.ref, z.ours));
    EXPECT_TRUE(same_bits(N_VWrmsNorm(x.ref, w.ref), N_VWrmsNorm(x.ours, w.ours)));
    EXPECT_TRUE(same_bits(N_VDotProd(x.ref, y.ref), N_VDotProd(x.ours, y.ours)));
    EXPECT_TRUE(same_bits(N_VMaxNorm(x.ref), N_VMaxNorm(x.ours)));
    EXPECT_TRUE(same_bits(N_VMin(x.ref), N_VMin(x.ours)));
    // Clones keep the compiled operations (CVODE's own vectors are clones of y).
    N_Vector clone = N_VClone(x.ours);
    EXPECT_EQ(clone->ops->nvlinearsum, x.ours->ops->nvlinearsum);
    EXPECT_NE(clone->ops->nvlinearsum, x.ref->ops->nvlinearsum);
    N_VDestroy(clone);
  }
}

TEST(SerialKernels, DenseSolverMatchesSunLinSolDenseBitForBit) {
  Context c;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (sunindextype n : {6, 9, 11}) {
    SUNMatrix Ar = SUNDenseMatrix(n, n, c.ctx), Ao = SUNDenseMatrix(n, n, c.ctx);
    for (sunindextype j = 0; j < n; ++j)
      for (sunindextype i = 0; i < n; ++i)
        SM_ELEMENT_D(Ar, i, j) = SM_ELEMENT_D(Ao, i, j) = u(rng) * (i == j ? 0.1 : 1.0);
    N_Vector b = N_VNew_Serial(n, c.ctx), xr = N_VNew_Serial(n, c.ctx),
             xo = N_VNew_Serial(n, c.ctx);
    for (sunindextype i = 0; i < n; ++i) NV_Ith_S(b, i) = u(rng);
    SUNLinearSolver ref = SUNLinSol_Dense(b, Ar, c.ctx);
    SUNLinearSolver ours = contensou::detail::compiled_dense_solver(b, Ao, c.ctx);
    ASSERT_NE(ours, nullptr);
    EXPECT_EQ(SUNLinSolGetType(ours), SUNLINEARSOLVER_DIRECT);
    ASSERT_EQ(SUNLinSolInitialize(ref), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolInitialize(ours), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ref, Ar), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSetup(ours, Ao), SUNLS_SUCCESS);
    EXPECT_EQ(std::memcmp(SUNDenseMatrix_Data(Ar), SUNDenseMatrix_Data(Ao),
                          sizeof(sunrealtype) * static_cast<std::size_t>(n * n)),
              0);  // the same factors
    ASSERT_EQ(SUNLinSolSolve(ref, Ar, xr, b, 0.0), SUNLS_SUCCESS);
    ASSERT_EQ(SUNLinSolSolve(ours, Ao, xo, b, 0.0), SUNLS_SUCCESS);
    EXPECT_TRUE(same_bits(xr, xo));
    // A singular matrix is reported as a failed factorisation.
    N_VConst(0.0, b);
    for (sunindextype i = 0; i < n; ++i) SM_ELEMENT_D(Ao, i, 2) = 0.0;
    EXPECT_EQ(SUNLinSolSetup(ours, Ao), SUNLS_LUFACT_FAIL);
    SUNLinSolFree(ref);
    SUNLinSolFree(ours);
    N_VDestroy(b);
    N_VDestroy(xr);
    N_VDestroy(xo);
    SUNMatDestroy(Ar);
    SUNMatDestroy(Ao);
  }
}
