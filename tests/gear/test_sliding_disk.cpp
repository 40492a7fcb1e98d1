// Known answer: a uniform disk with uniform pressure, sliding and spinning on a plane, stops
// both motions at the same instant, and v/(omega R) tends to 0.6530 with the exact law
// (Farkas, Bartels, Unger & Wolf, PRL 90, 248302, 2003). Integrated with SUNDIALS CVODE (BDF).
#include <cvode/cvode.h>
#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "closed_forms.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"

using namespace contensou;

namespace {

// Units: M = R = mu g = 1, so F0 = mu N = 1 and I = M R^2 / 2 = 1/2.
ContactPatch unit_disk() {
  ContactPatch p;
  p.radius_m = 1.0;
  p.reference_pressure_pa = 1.0 / std::numbers::pi;  // N = pi R^2 p* = 1
  p.friction = 1.0;
  p.profile = uniform_profile();
  return p;
}

using Law = std::function<Resultants<double>(double v, double omega)>;

struct Motion {
  double ratio_at_stop = 0.0;   // v / (omega R) when v + omega R falls to 1e-10
  double t_v = 0.0, t_w = 0.0;  // times when v and omega R fall below 1e-4 of their start
  double t_stop = 0.0;
};

int rhs(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const Law& law = *static_cast<const Law*>(data);
  const double v = std::max(NV_Ith_S(y, 0), 0.0), w = std::max(NV_Ith_S(y, 1), 0.0);
  const Resultants<double> r = law(v, w);
  NV_Ith_S(ydot, 0) = r.Fx;        // M dv/dt = Fx
  NV_Ith_S(ydot, 1) = r.Mz / 0.5;  // I domega/dt = Mz
  return 0;
}

int stop_root(sunrealtype, N_Vector y, sunrealtype* g, void*) {
  g[0] = NV_Ith_S(y, 0) + NV_Ith_S(y, 1) - 1e-10;
  return 0;
}

Motion slide(Law law, double v0, double w0) {
  SUNContext ctx;
  EXPECT_EQ(SUNContext_Create(nullptr, &ctx), 0);
  N_Vector y = N_VNew_Serial(2, ctx);
  NV_Ith_S(y, 0) = v0;
  NV_Ith_S(y, 1) = w0;
  void* cv = CVodeCreate(CV_BDF, ctx);
  CVodeInit(cv, rhs, 0.0, y);
  CVodeSStolerances(cv, 1e-9, 1e-16);
  SUNMatrix A = SUNDenseMatrix(2, 2, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  CVodeSetLinearSolver(cv, LS, A);
  CVodeSetUserData(cv, &law);
  CVodeRootInit(cv, 1, stop_root);
  CVodeSetMaxNumSteps(cv, 100000);
  Motion m;
  double t = 0.0;
  const double tend = 10.0 * (v0 + w0);
  while (t < tend) {
    const int flag = CVode(cv, tend, y, &t, CV_ONE_STEP);
    EXPECT_GE(flag, 0) << "CVODE flag " << flag;
    if (flag < 0) break;
    if (m.t_v == 0.0 && NV_Ith_S(y, 0) < 1e-4 * v0) m.t_v = t;
    if (m.t_w == 0.0 && NV_Ith_S(y, 1) < 1e-4 * w0) m.t_w = t;
    if (flag == CV_ROOT_RETURN) {
      m.ratio_at_stop = NV_Ith_S(y, 0) / NV_Ith_S(y, 1);
      m.t_stop = t;
      break;
    }
  }
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y);
  CVodeFree(&cv);
  SUNContext_Free(&ctx);
  return m;
}

}  // namespace

TEST(SlidingDisk, ClosedFormsGiveFarkasRatio) {
  EXPECT_NEAR(test_support::sliding_disk_fixed_point(), 0.6530, 5e-4);
}

TEST(SlidingDisk, ExactLawStopsBothMotionsTogetherAtFarkasRatio) {
  const ExactModel<double> model = make_exact_model(unit_disk());
  const Law exact = [&](double v, double w) {
    return exact_resultants(model, Kinematics<double>{v, 0.0, w}, {1e-11}).resultants;
  };
  for (auto [v0, w0] : {std::pair{1.0, 1.0}, std::pair{3.0, 0.5}, std::pair{0.2, 2.0}}) {
    const Motion m = slide(exact, v0, w0);
    EXPECT_NEAR(m.ratio_at_stop, 0.6530, 2e-3) << v0 << " " << w0;
    // Both reach 1e-4 of their start within a small fraction of the stopping time.
    EXPECT_LT(std::abs(m.t_v - m.t_w), 2e-3 * m.t_stop) << v0 << " " << w0;
    EXPECT_GT(m.t_stop, 0.0);
  }
}

TEST(SlidingDisk, FractionalLawRatioIsItsOwnFixedPoint) {
  // Uniform pressure: a = 1, m = 64/9, M0 = (2/3) F0 R. Equal decay rates give
  // 1/sqrt(e^2 + 1) = (4/3) / sqrt(1 + 64 e^2 / 9), i.e. e = sqrt(7/48) = 0.3819.
  FractionalLaw<double> law = fractional_law_from_patch(unit_disk());
  law.regularization_speed = 1e-15;  // far below the stopping speed 1e-10
  const Law frac = [&](double v, double w) {
    return fractional_resultants(law, Kinematics<double>{v, 0.0, w});
  };
  const Motion m = slide(frac, 1.0, 1.0);
  EXPECT_NEAR(m.ratio_at_stop, std::sqrt(7.0 / 48.0), 2e-3);
  RecordProperty("fractional_ratio", std::to_string(m.ratio_at_stop));
}
