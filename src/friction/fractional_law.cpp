#include "contensou/friction/fractional_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"

namespace contensou {

void validate(const FractionalLaw<double>& p) {
  detail::check_law(p);
  // The pressure p* p(rho) (1 + kx x/R + ky y/R) stays positive on the patch only for
  // |(kx, ky)| < 1 (theory.md section 2, seed eq. 9), as validate(ContactPatch) requires.
  const double k = std::hypot(p.kx, p.ky);
  if (!(k < 1.0))
    throw InvalidArgument("|(kx, ky)|", format_value(k),
                          "the pressure shift must be < 1 so that the pressure stays positive");
  // The scales 0 or normal doubles, as loads and radii are (require_positive): a subnormal one
  // has lost its precision (the law's evaluation accepts it; validate, which every binding calls
  // first, refuses it).
  const std::pair<const char*, double> scales[] = {{"F0", p.F0}, {"M0", p.M0}, {"Mk", p.Mk}};
  for (const auto& [name, v] : scales)
    if (v > 0.0 && v < std::numeric_limits<double>::min())
      throw InvalidArgument(
          name, format_value(v),
          "is below 2.2e-308, the smallest normal double: use other units (or 0)");
}

namespace {

// Velocities scaled by sc = max(|vx|, |vy|, |omega| R, eps) (the law is homogeneous of degree
// 0 in (v, u, eps): J is divided by sc at the end): v, u = omega R, eps^2, U = u^2, q = |v|^2.
struct ScaledKinematics {
  double vx, vy, u, e2, U, q, R;
};

// The shift forces -(M0/2R) [g2 (z x k) + Gq (k.v)(z x v)] and their Jacobian (theory.md
// section 4; Gq = (g1 - g2)/q in the cancellation-free form of the header: Gq = u L, L = P / Q,
// Q = S1 S2^3 Wq, Wq = S2^3 + s0 S1, s0 = U + eps^2; derivatives in q and s0, ds0/du = 2u).
void add_shift_forces(const FractionalLaw<double>& p, const ScaledKinematics& k, double& Fx,
                      double& Fy, Eigen::Matrix3d& J) {
  const double vx = k.vx, vy = k.vy, u = k.u, e2 = k.e2, U = k.U, q = k.q, R = k.R;
  const double hm = p.M0 / (2.0 * R);
  const double s0 = U + e2, c = p.c;
  const double S1 = std::sqrt(s0 + 0.25 * p.m * q), iS12 = 1.0 / (S1 * S1);
  const double S2sq = s0 + c * q, S2 = std::sqrt(S2sq), iS22 = 1.0 / S2sq;
  const double S23 = S2sq * S2, iS23 = 1.0 / S23, iS25 = iS23 * iS22;
  const double g2 = u * s0 * iS23;
  const double dg2_dq = -1.5 * c * u * s0 * iS25;
  const double dg2_du = (s0 * e2 + c * q * (s0 + 2.0 * U)) * iS25;
  const double P = s0 * s0 * (3.0 * c - 0.25 * p.m) + 3.0 * s0 * c * c * q + c * c * c * q * q;
  const double Wq = S23 + s0 * S1, iQ = 1.0 / (S1 * S23 * Wq);
  const double L = P * iQ;
  const double P_q = 3.0 * s0 * c * c + 2.0 * c * c * c * q;
  const double P_s = 2.0 * s0 * (3.0 * c - 0.25 * p.m) + 3.0 * c * c * q;
  const double W_q = 1.5 * c * S2 + 0.125 * p.m * s0 / S1;
  const double W_s = 1.5 * S2 + S1 + 0.5 * s0 / S1;
  const double lnQ_q = 0.125 * p.m * iS12 + 1.5 * c * iS22 + W_q / Wq;
  const double lnQ_s = 0.5 * iS12 + 1.5 * iS22 + W_s / Wq;
  const double Gq = u * L;
  const double dGq_dq = u * (P_q - P * lnQ_q) * iQ;
  const double dGq_du = L + 2.0 * U * (P_s - P * lnQ_s) * iQ;
  Fx += hm * g2 * p.ky;
  Fy -= hm * g2 * p.kx;
  const double dg2[3] = {2 * vx * dg2_dq, 2 * vy * dg2_dq, R * dg2_du};
  for (int j = 0; j < 3; ++j) {
    J(0, j) += hm * dg2[j] * p.ky;
    J(1, j) -= hm * dg2[j] * p.kx;
  }
  const double kv = p.kx * vx + p.ky * vy, H = Gq * kv;
  Fx += hm * H * vy;
  Fy -= hm * H * vx;
  const double dH_dvx = 2 * vx * dGq_dq * kv + Gq * p.kx;
  const double dH_dvy = 2 * vy * dGq_dq * kv + Gq * p.ky;
  const double dH_dw = R * dGq_du * kv;
  J(0, 0) += hm * dH_dvx * vy;
  J(0, 1) += hm * (dH_dvy * vy + H);
  J(0, 2) += hm * dH_dw * vy;
  J(1, 0) -= hm * (dH_dvx * vx + H);
  J(1, 1) -= hm * dH_dvy * vx;
  J(1, 2) -= hm * dH_dw * vx;
}

// The cross-shift torque Mk W q / Sk^3, W = vx ky - kappa vy kx, Sk = (q + a_k U + eps^2)^(1/2)
// (theory.md section 4), and its Jacobian.
void add_cross_shift_torque(const FractionalLaw<double>& p, const ScaledKinematics& k, double& Mz,
                            Eigen::Matrix3d& J) {
  const double vx = k.vx, vy = k.vy, u = k.u, q = k.q, R = k.R;
  const double W = vx * p.ky - p.kappa * vy * p.kx;
  const double iSk = 1.0 / std::sqrt(q + p.a_k * k.U + k.e2), iSk2 = iSk * iSk;
  const double iSk3 = iSk2 * iSk, iSk5 = iSk3 * iSk2;
  Mz += p.Mk * W * q * iSk3;
  J(2, 0) += p.Mk * ((p.ky * q + W * 2 * vx) * iSk3 - 3 * W * q * vx * iSk5);
  J(2, 1) += p.Mk * ((-p.kappa * p.kx * q + W * 2 * vy) * iSk3 - 3 * W * q * vy * iSk5);
  J(2, 2) += -3 * p.Mk * W * q * p.a_k * u * R * iSk5;
}

}  // namespace

// The fractional law and its Jacobian (theory.md section 4): sliding force -F0 (vx, kappa vy) /
// Sa, spin torque -M0 (1 + kappa)/2 u / Sm, and with a shift the shift forces and the
// cross-shift torque; on scaled velocities, one reciprocal per square root.
FractionalWithJacobian fractional_resultants_with_jacobian(const FractionalLaw<double>& p,
                                                           const Kinematics<double>& k0) {
  detail::check_law(p);
  detail::check_kinematics(k0.vx, k0.vy, k0.omega, p.radius);
  // Homogeneous of degree 0 in (v, u, eps): evaluate on scaled velocities, divide J by s.
  // One reciprocal per square root; everything else is multiplication.
  const double R = p.radius;
  const double sc =
      std::max({std::abs(k0.vx), std::abs(k0.vy), std::abs(k0.omega) * R, p.regularization_speed});
  const double isc = 1.0 / sc;
  const double vx = k0.vx * isc, vy = k0.vy * isc, u = k0.omega * R * isc;
  const double e = p.regularization_speed * isc, e2 = e * e;
  const double U = u * u, q = vx * vx + vy * vy;
  FractionalWithJacobian out;
  Eigen::Matrix3d& J = out.jacobian;
  // Sliding force -F0 (vx, kappa vy) / Sa.
  const double iSa = 1.0 / std::sqrt(q + p.a * U + e2), iSa3 = iSa * iSa * iSa;
  const double F0k = p.F0 * p.kappa;
  double Fx = -p.F0 * vx * iSa, Fy = -F0k * vy * iSa;
  J(0, 0) = -p.F0 * (iSa - vx * vx * iSa3);
  J(0, 1) = p.F0 * vx * vy * iSa3;
  J(1, 0) = F0k * vx * vy * iSa3;
  J(1, 1) = -F0k * (iSa - vy * vy * iSa3);
  J(0, 2) = p.F0 * vx * p.a * u * R * iSa3;
  J(1, 2) = F0k * vy * p.a * u * R * iSa3;
  // Spin torque -M0 (1 + kappa)/2 u / Sm.
  const double Mks = p.M0 * 0.5 * (1.0 + p.kappa);
  const double iSm = 1.0 / std::sqrt(U + p.m * q + e2), iSm3 = iSm * iSm * iSm;
  double Mz = -Mks * u * iSm;
  J(2, 0) = Mks * u * p.m * vx * iSm3;
  J(2, 1) = Mks * u * p.m * vy * iSm3;
  J(2, 2) = -Mks * R * (p.m * q + e2) * iSm3;
  if (p.kx != 0.0 || p.ky != 0.0) {
    const ScaledKinematics k{vx, vy, u, e2, U, q, R};
    add_shift_forces(p, k, Fx, Fy, J);
    add_cross_shift_torque(p, k, Mz, J);
  }
  out.resultants = {Fx, Fy, Mz};
  J *= isc;
  return out;
}

namespace {

struct ProfileMoments {
  double A0, A1, A2, A3, A5;
};

ProfileMoments moments_of(const PressureProfile& prof) {
  return {moment(prof, 0), moment(prof, 1), moment(prof, 2), moment(prof, 3), moment(prof, 5)};
}

// Minimises g(x) over [lo, hi] by golden-section search (g unimodal near its optimum).
template <class G>
double golden_minimum(G&& g, double lo, double hi, int iterations = 60) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi, c = b - r * (b - a), d = a + r * (b - a);
  double gc = g(c), gd = g(d);
  for (int i = 0; i < iterations; ++i) {
    if (gc < gd) {
      b = d;
      d = c;
      gd = gc;
      c = b - r * (b - a);
      gc = g(c);
    } else {
      a = c;
      c = d;
      gc = gd;
      d = a + r * (b - a);
      gd = g(d);
    }
  }
  return 0.5 * (a + b);
}

// Cross-shift torque of the exact integrals at psi = v/u, sliding along x, divided by ky.
double exact_cross_torque(const ExactModel<double>& shifted, const ExactModel<double>& plain,
                          double R, double psi) {
  const Kinematics<double> k{psi, 0.0, 1.0 / R};
  const double with = exact_resultants(shifted, k, {1e-11}).resultants.Mz;
  const double without = exact_resultants(plain, k, {1e-11}).resultants.Mz;
  return (with - without) / value_of(shifted.ky);
}

}  // namespace

FractionalLaw<double> fractional_law_from_patch(const ContactPatch& patch) {
  validate(patch);
  const ProfileMoments A = moments_of(patch.profile);
  if (!(A.A0 > 0.0 && A.A1 > 0.0 && A.A2 > 0.0 && A.A3 > 0.0 && A.A5 > 0.0))
    throw InvalidArgument("profile", describe(patch.profile),
                          "moments A^0..A^5 must be positive for the fractional law");
  const double R = patch.radius_m, ps = patch.reference_pressure_pa;
  const double f =
      patch.slip_speed_friction ? patch.slip_speed_friction->kinetic_coefficient : patch.friction;
  FractionalLaw<double> law;
  law.radius = R;
  law.F0 = f * 2.0 * std::numbers::pi * R * R * ps * A.A1;
  law.M0 = 2.0 * std::numbers::pi * f * R * R * R * ps * A.A2;
  law.a = std::pow(2.0 * A.A1 / A.A0, 2);
  law.m = std::pow(2.0 * A.A2 / A.A3, 2);
  law.c = std::pow(4.0 * A.A2 / A.A5, 2.0 / 3.0);
  law.Mk = std::numbers::pi * f * R * R * R * ps * A.A3;
  law.kx = patch.profile.kx;
  law.ky = patch.profile.ky;
  law.kappa = patch.kappa;
  // a_k from the exact small-sliding asymptote Mz_k -> Mk ky psi^3 / a_k^(3/2) (psi = v/u << 1).
  ContactPatch shifted = patch;
  shifted.profile.kx = 0.0;
  shifted.profile.ky = 0.1;
  shifted.kappa = 1.0;
  shifted.slip_speed_friction.reset();
  shifted.friction = f > 0.0 ? f : 1.0;
  ContactPatch plain = shifted;
  plain.profile.ky = 0.0;
  const ExactModel<double> ms = make_exact_model(shifted), mp = make_exact_model(plain);
  const double psi = 1e-2;
  const double mk_unit = std::numbers::pi * shifted.friction * R * R * R * ps * A.A3;
  const double tq = exact_cross_torque(ms, mp, R, psi);
  law.a_k = tq > 0.0 ? std::pow(mk_unit * psi * psi * psi / tq, 2.0 / 3.0) : 1.0;
  return law;
}

FractionalLaw<double> fractional_law_fitted(const ContactPatch& patch, double psi_min,
                                            double psi_max, int n) {
  require_positive("psi_min", psi_min);
  if (!(psi_max > psi_min))
    throw InvalidArgument("psi_max", format_value(psi_max), "must exceed psi_min");
  if (n < 3) throw InvalidArgument("n", std::to_string(n), "need at least 3 ratios");
  FractionalLaw<double> law = fractional_law_from_patch(patch);
  ContactPatch iso = patch;
  iso.kappa = 1.0;
  iso.profile.kx = iso.profile.ky = 0.0;
  const ExactModel<double> model = make_exact_model(iso);
  const double R = patch.radius_m;
  std::vector<double> psi(n), fpar(n), mz(n);
  for (int i = 0; i < n; ++i) {
    psi[i] = psi_min * std::pow(psi_max / psi_min, static_cast<double>(i) / (n - 1));
    const auto r = exact_resultants(model, Kinematics<double>{psi[i], 0.0, 1.0 / R}, {1e-10});
    fpar[i] = -r.resultants.Fx;
    mz[i] = -r.resultants.Mz;
  }
  const FractionalLaw<double> base = law;
  auto sse = [&](double log_value, bool force) {
    FractionalLaw<double> trial = base;
    trial.kx = trial.ky = 0.0;
    trial.kappa = 1.0;
    (force ? trial.a : trial.m) = std::exp(log_value);
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
      const auto r = fractional_resultants(trial, Kinematics<double>{psi[i], 0.0, 1.0 / R});
      const double e = force ? (-r.Fx - fpar[i]) / base.F0 : (-r.Mz - mz[i]) / base.M0;
      s += e * e;
    }
    return s;
  };
  law.a = std::exp(golden_minimum([&](double x) { return sse(x, true); }, std::log(base.a) - 3.0,
                                  std::log(base.a) + 3.0));
  law.m = std::exp(golden_minimum([&](double x) { return sse(x, false); }, std::log(base.m) - 3.0,
                                  std::log(base.m) + 3.0));
  return law;
}

}  // namespace contensou
