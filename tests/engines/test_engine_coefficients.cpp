// The converter's coefficients and worst errors against closed forms: uniform pressure's
// Contensou integrals (theory.md section 3) and the pure-spin torques of uniform ((2/3) f N R)
// and Hertz ((3 pi/16) f N R) pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "closed_forms.hpp"
#include "coefficients.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"

using namespace contensou;
using namespace contensou::engines;

namespace {

using test_support::uniform_closed_form;

const EngineCoefficient& row(const std::vector<EngineCoefficient>& rows, const std::string& engine,
                             int which = 0) {
  for (const auto& r : rows)
    if (r.engine.rfind(engine, 0) == 0 && which-- == 0) return r;
  throw std::runtime_error("no row " + engine);
}

}  // namespace

TEST(EngineCoefficients, UniformPureSpinIsTwoThirdsRf) {
  const double R = 0.07, f = 0.4;
  const auto rows = engine_coefficients(named_patch("uniform", R, f));
  EXPECT_NEAR(row(rows, "MuJoCo").value, 2.0 / 3.0 * R * f, 1e-12);
  EXPECT_NEAR(row(rows, "Chrono").value, 2.0 / 3.0 * R * f, 1e-12);
  EXPECT_NEAR(row(rows, "Bullet").value, 2.0 / 3.0 * R * f, 1e-12);
  // Gazebo: (3 pi/16) f a N = (2/3) f R N.
  EXPECT_NEAR(row(rows, "Gazebo").value, (2.0 / 3.0) * R / (3 * std::numbers::pi / 16), 1e-12);
  EXPECT_NE(row(rows, "MuJoCo").snippet.find("condim=\"4\""), std::string::npos);
}

TEST(EngineCoefficients, HertzPatchRadiusIsTheRadius) {
  const double R = 0.02, f = 0.8;
  const auto rows = engine_coefficients(named_patch("hertz", R, f));
  EXPECT_NEAR(row(rows, "MuJoCo").value, 3 * std::numbers::pi / 16 * R * f, 1e-12);
  EXPECT_NEAR(row(rows, "Gazebo").value, R, 1e-12);
}

TEST(EngineCoefficients, WorstErrorsMatchTheClosedForms) {
  const double R = 0.1, f = 0.5;
  Grid g;
  const auto rows = engine_coefficients(named_patch("uniform", R, f), g);
  // The elliptic cone at pure spin, c = 2/3 (header of coefficients.hpp), on the same grid.
  double ef = 0, em = 0, uf = 0, um = 0;
  for (int i = 0; i < g.points; ++i) {
    const double psi = g.psi_min * std::pow(g.psi_max / g.psi_min, double(i) / (g.points - 1));
    auto [fp, mz] = uniform_closed_form(psi);
    mz /= 2.0 / 3.0;  // relative to the pure-spin torque
    const double c = 2.0 / 3.0, s = std::hypot(psi, c);
    ef = std::max(ef, std::abs(psi / s - fp));
    em = std::max(em, std::abs(c / s - mz));
    uf = std::max(uf, std::abs(1 - fp));
    um = std::max(um, std::abs(1 - mz));
  }
  EXPECT_NEAR(row(rows, "MuJoCo").worst_force_error, ef, 1e-7);
  EXPECT_NEAR(row(rows, "MuJoCo").worst_torque_error, em, 1e-7);
  EXPECT_NEAR(row(rows, "Chrono").worst_force_error, uf, 1e-7);
  EXPECT_NEAR(row(rows, "Chrono").worst_torque_error, um, 1e-7);
  // The least-squares coefficient fits no worse in the squared sense, so its errors stay close.
  EXPECT_LT(std::abs(row(rows, "MuJoCo", 1).value / row(rows, "MuJoCo").value - 1), 0.1);
}

TEST(EngineCoefficients, BadInputNamesTheOption) {
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message([] { named_patch("cone", 0.1, 0.5); }).find("--profile = 'cone'"),
            std::string::npos);
  EXPECT_NE(message([] { named_patch("uniform", -2, 0.5); }).find("--radius = -2"),
            std::string::npos);
  EXPECT_NE(message([] { named_patch("uniform", 0.1, NAN); }).find("--friction = nan"),
            std::string::npos);
}

// The curves come from the exact law (exact_law.hpp): on the seed tire (a profile without closed
// forms) the worst errors of the pure-spin rows equal those from the adaptive integrator at a
// tighter tolerance on the same grid, to the law's tolerance (1e-9 of F0 and f N R).
TEST(EngineCoefficients, ExactLawCurvesAgreeWithTheIntegrator) {
  const double R = 0.087, f = 0.3;
  const ContactPatch patch = named_patch("seed-tire", R, f);
  Grid g;
  g.points = 41;
  const auto rows = engine_coefficients(patch, g);
  const ExactModel<double> model = make_exact_model(patch);
  const double N = normal_load(patch), F0 = f * N, M0 = spin_torque_per_load(patch) * N;
  const double c = M0 / (F0 * R);  // the elliptic cone at pure spin (coefficients.hpp)
  double ef = 0, em = 0, uf = 0, um = 0;
  for (int i = 0; i < g.points; ++i) {
    const double psi = g.psi_min * std::pow(g.psi_max / g.psi_min, double(i) / (g.points - 1));
    const auto r = exact_resultants(model, Kinematics<double>{psi, 0.0, 1.0 / R}, {1e-12});
    const double fp = -r.resultants.Fx / F0, mz = -r.resultants.Mz / M0;
    const double s = std::hypot(psi, c);
    ef = std::max(ef, std::abs(psi / s - fp));
    em = std::max(em, std::abs(c / s - mz));
    uf = std::max(uf, std::abs(1 - fp));
    um = std::max(um, std::abs(1 - mz));
  }
  // Torques relative to M0 = f N R A^2 / A^1: the law's bound 1e-9 f N R is (A^1 / A^2) 1e-9 of M0.
  const double tol_f = 1e-9, tol_m = 1e-9 * F0 * R / M0;
  EXPECT_NEAR(row(rows, "MuJoCo").worst_force_error, ef, tol_f);
  EXPECT_NEAR(row(rows, "MuJoCo").worst_torque_error, em, tol_m);
  EXPECT_NEAR(row(rows, "Chrono").worst_force_error, uf, tol_f);
  EXPECT_NEAR(row(rows, "Chrono").worst_torque_error, um, tol_m);
}
