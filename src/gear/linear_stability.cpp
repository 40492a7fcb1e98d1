#include "contensou/gear/linear_stability.hpp"

#include "cvode_handles.hpp"
#include "serial_kernels.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "contensou/friction/error.hpp"
#include "contensou/gear/oscillation.hpp"

namespace contensou {

namespace {

// The states' scales (landing_gear.hpp, kStateScale).
constexpr const std::array<double, kStateSize>& kScale = kStateScale;

double scale_of(int i) {
  return kScale[static_cast<std::size_t>(i)];
}

double scaled_residual(const GearState& f, const std::vector<int>& states) {
  double r = 0.0;
  for (int i : states) r = std::max(r, std::abs(f[i]) / scale_of(i));
  return r;
}

// Longitudinal relaxation: u_i = sigma_x vx_i / V at the quasi-steady state; Newton starts from
// the phase's slip.
void add_longitudinal_states(const GearModel& model, StabilityPhase phase, double touchdown_slip,
                             QuasiSteadyState& q) {
  const double sigma_x = model.config.tire.longitudinal_relaxation_length_m;
  if (!(sigma_x > 0.0)) return;
  const bool sliding = model.contact != ContactModel::von_schlippe;
  const double slip = phase == StabilityPhase::braked_slide
                          ? model.config.scenario.brake_target_slip
                      : sliding && phase == StabilityPhase::touchdown ? touchdown_slip
                                                                      : 0.0;
  q.states.push_back(kSlipX);
  q.x[kSlipX] = sigma_x * slip;
  if (model.config.structure.wheel_spacing_m > 0.0) {
    q.states.push_back(kSlipX2);
    q.x[kSlipX2] = q.x[kSlipX];
  }
}

}  // namespace

GearState quasi_steady_rhs(const GearModel& model, const QuasiSteadyState& q, const GearState& x) {
  GearState dx = gear_rhs(model, q.mode, q.t, x);
  if (q.frozen_spin) dx[kSpin] = dx[kSpin2] = 0.0;
  return dx;
}

QuasiSteadyState quasi_steady_state(const GearModel& model, StabilityPhase phase,
                                    double touchdown_slip) {
  const LandingScenario& s = model.config.scenario;
  const double V = s.forward_speed_mps, r = model.config.structure.wheel_radius_m;
  const bool sliding = model.contact != ContactModel::von_schlippe;
  const bool twin = model.config.structure.wheel_spacing_m > 0.0;
  QuasiSteadyState q;
  q.phase = phase;
  q.mode.loaded = true;
  q.mode.rolling = !sliding;
  q.mode.brake_command = phase == StabilityPhase::braked_slide;
  q.t = s.touchdown_time_s + s.load_ramp_s + 1.0;
  q.states = {kY, kYDot, kPsi, kPsiDot};
  if (phase == StabilityPhase::touchdown && sliding) {
    if (!(touchdown_slip > 0.0 && touchdown_slip <= 1.0))
      throw InvalidArgument("touchdown slip", format_value(touchdown_slip), "must lie in (0, 1]");
    q.frozen_spin = true;
    q.touchdown_slip = touchdown_slip;
    q.x[kSpin] = V * (1.0 - touchdown_slip) / r;
    q.x[kSpin2] = twin ? q.x[kSpin] : 0.0;
  } else {
    q.states.push_back(kSpin);
    q.x[kSpin] =
        phase == StabilityPhase::braked_slide ? V * (1.0 - s.brake_target_slip) / r : V / r;
    if (twin) {
      q.states.push_back(kSpin2);
      q.x[kSpin2] = q.x[kSpin];
    }
  }
  if (!sliding) q.states.push_back(kLambda);
  if (model.config.structure.fore_aft_stiffness_n_per_m > 0.0) {
    q.states.push_back(kX);
    q.states.push_back(kXDot);
  }
  if (model.config.structure.carcass_compliance()) {
    q.states.push_back(kCarcassY);
    q.states.push_back(kCarcassPsi);
  }
  add_longitudinal_states(model, phase, touchdown_slip, q);

  // Newton's method with a central-difference Jacobian and step halving.
  const int n = static_cast<int>(q.states.size());
  const auto residual_vector = [&](const GearState& x) {
    const GearState f = quasi_steady_rhs(model, q, x);
    Eigen::VectorXd v(n);
    for (int k = 0; k < n; ++k)
      v[k] = f[q.states[static_cast<std::size_t>(k)]] /
             scale_of(q.states[static_cast<std::size_t>(k)]);
    return v;
  };
  Eigen::VectorXd f = residual_vector(q.x);
  for (int iter = 0; iter < 60 && f.allFinite(); ++iter) {
    // The residual is the reduced right-hand side over the state scales: J = S^-1 A.
    Eigen::MatrixXd J = linearise(model, q);
    for (int k = 0; k < n; ++k) J.row(k) /= scale_of(q.states[static_cast<std::size_t>(k)]);
    const Eigen::VectorXd step = -J.colPivHouseholderQr().solve(f);
    if (!step.allFinite()) break;
    double lambda = 1.0;
    GearState trial = q.x;
    Eigen::VectorXd ft = f;
    for (int halving = 0; halving < 30; ++halving, lambda *= 0.5) {
      trial = q.x;
      for (int k = 0; k < n; ++k) trial[q.states[static_cast<std::size_t>(k)]] += lambda * step[k];
      ft = residual_vector(trial);
      if (ft.allFinite() && ft.norm() < f.norm()) break;
    }
    double size = 0.0;
    for (int k = 0; k < n; ++k)
      size = std::max(size,
                      std::abs(lambda * step[k]) / scale_of(q.states[static_cast<std::size_t>(k)]));
    q.x = trial;
    f = ft;
    if (size < 1e-11 || f.lpNorm<Eigen::Infinity>() < 1e-12) break;
  }
  q.residual = scaled_residual(quasi_steady_rhs(model, q, q.x), q.states);
  q.converged = std::isfinite(q.residual) && q.residual < 1e-6;
  return q;
}

Eigen::MatrixXd linearise(const GearModel& model, const QuasiSteadyState& q) {
  const int n = static_cast<int>(q.states.size());
  Eigen::MatrixXd A(n, n);
  for (int k = 0; k < n; ++k) {
    const int j = q.states[static_cast<std::size_t>(k)];
    const double h = 1e-6 * scale_of(j);
    GearState xp = q.x, xm = q.x;
    xp[j] += h;
    xm[j] -= h;
    const GearState d = (quasi_steady_rhs(model, q, xp) - quasi_steady_rhs(model, q, xm)) / (2 * h);
    for (int l = 0; l < n; ++l) A(l, k) = d[q.states[static_cast<std::size_t>(l)]];
  }
  return A;
}

namespace {

// Rows Fx, Fy, Mz, lateral force on the strut (Fx sin psi + Fy cos psi); one column per state.
Eigen::Matrix<double, 4, kStateSize> contact_jacobian(const GearModel& model,
                                                      const QuasiSteadyState& q) {
  const auto forces = [&](const GearState& x) {
    const ContactState c = contact_state(model, q.mode, q.t, x);
    return Eigen::Vector4d(c.force.Fx, c.force.Fy, c.force.Mz,
                           c.force.Fx * std::sin(x[kPsi]) + c.force.Fy * std::cos(x[kPsi]));
  };
  Eigen::Matrix<double, 4, kStateSize> J;
  for (int j = 0; j < kStateSize; ++j) {
    const double h = 1e-6 * scale_of(j);
    GearState xp = q.x, xm = q.x;
    xp[j] += h;
    xm[j] -= h;
    J.col(j) = (forces(xp) - forces(xm)) / (2 * h);
  }
  return J;
}

// CVODE on the quasi-steady problem in its fixed mode: the response to the standard
// perturbation (no events: the mode does not change).
struct FixedModeProblem {
  const GearModel* model;
  const QuasiSteadyState* q;
};

int fixed_rhs(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const FixedModeProblem& p = *static_cast<const FixedModeProblem*>(data);
  GearState x;
  for (int i = 0; i < kStateSize; ++i) x[i] = NV_Ith_S(y, i);
  const GearState dx = quasi_steady_rhs(*p.model, *p.q, x);
  for (int i = 0; i < kStateSize; ++i) {
    if (!std::isfinite(dx[i])) return 1;
    NV_Ith_S(ydot, i) = dx[i];
  }
  return 0;
}

using Cvode = detail::CvodeHandles;

void check(int flag, const char* what) {
  if (flag < 0)
    throw std::runtime_error(std::string("CVODE ") + what + " failed with flag " +
                             std::to_string(flag) + " (perturbation run)");
}

OscillationEstimate perturbation_response(const GearModel& model, const QuasiSteadyState& q,
                                          const StabilityOptions& o) {
  FixedModeProblem problem{&model, &q};
  Cvode cv;
  check(SUNContext_Create(nullptr, &cv.ctx), "SUNContext_Create");
  cv.y = N_VNew_Serial(kStateSize, cv.ctx);
  cv.atol = N_VNew_Serial(kStateSize, cv.ctx);
  detail::use_compiled_vector_ops(cv.y);  // serial_kernels.hpp: the same arithmetic, compiled
  detail::use_compiled_vector_ops(cv.atol);
  const double rtol = 1e-8;
  for (int i = 0; i < kStateSize; ++i) {
    NV_Ith_S(cv.y, i) = q.x[i] + (i == kPsiDot ? o.perturbation_rate_radps : 0.0);
    NV_Ith_S(cv.atol, i) = rtol * 1e-3 * scale_of(i);
  }
  cv.mem = CVodeCreate(CV_BDF, cv.ctx);
  check(CVodeInit(cv.mem, fixed_rhs, q.t, cv.y), "CVodeInit");
  check(CVodeSVtolerances(cv.mem, rtol, cv.atol), "CVodeSVtolerances");
  cv.A = SUNDenseMatrix(kStateSize, kStateSize, cv.ctx);
  cv.LS = detail::compiled_dense_solver(cv.y, cv.A, cv.ctx);
  if (!cv.LS)
    throw std::runtime_error("CVODE linear solver could not be created (perturbation run)");
  check(CVodeSetLinearSolver(cv.mem, cv.LS, cv.A), "CVodeSetLinearSolver");
  check(CVodeSetUserData(cv.mem, &problem), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(cv.mem, 200000), "CVodeSetMaxNumSteps");
  const double dt = 2.5e-4;
  const int samples = static_cast<int>(std::ceil(o.perturbation_window_s / dt));
  std::vector<double> t{0.0}, rate{NV_Ith_S(cv.y, kPsiDot) - q.x[kPsiDot]}, psi{0.0};
  double tc = q.t;
  for (int k = 1; k <= samples; ++k) {
    check(CVode(cv.mem, q.t + k * dt, cv.y, &tc, CV_NORMAL), "CVode");
    t.push_back(tc - q.t);
    rate.push_back(NV_Ith_S(cv.y, kPsiDot) - q.x[kPsiDot]);
    psi.push_back(NV_Ith_S(cv.y, kPsi) - q.x[kPsi]);
  }
  return analyse_oscillation(t, rate, psi);
}

// The position of `state` among the quasi-steady state's active states; -1 if inactive.
int index_of(const QuasiSteadyState& q, int state) {
  for (std::size_t k = 0; k < q.states.size(); ++k)
    if (q.states[k] == state) return static_cast<int>(k);
  return -1;
}

// The mode's longitudinal tire deflection |u| + |u2| (the wheel-tire longitudinal mode the
// longitudinal relaxation adds; 0 without it).
double longitudinal_deflection(const QuasiSteadyState& q, const Eigen::VectorXcd& v) {
  double u = 0.0;
  for (int state : {static_cast<int>(kSlipX), static_cast<int>(kSlipX2)}) {
    const int k = index_of(q, state);
    if (k >= 0) u += std::abs(v[k]);
  }
  return u;
}

// The work per cycle of each term along the mode v (complex amplitudes of the active states,
// angular frequency w), the contact forces along it from Jc (linear_stability.hpp).
EnergyPerCycle mode_energy(const GearModel& model, const QuasiSteadyState& q,
                           const Eigen::Matrix<double, 4, kStateSize>& Jc,
                           const Eigen::VectorXcd& v, double w) {
  Eigen::Vector4cd F = Eigen::Vector4cd::Zero();
  for (std::size_t k = 0; k < q.states.size(); ++k)
    F += Jc.col(q.states[k]).cast<std::complex<double>>() * v[static_cast<int>(k)];
  const std::complex<double> psi_dot = v[index_of(q, kPsiDot)], y_dot = v[index_of(q, kYDot)];
  const auto work = [&](std::complex<double> force, std::complex<double> rate) {
    return std::numbers::pi / w * (force * std::conj(rate)).real();
  };
  const GearStructure& g = model.config.structure;
  EnergyPerCycle e;
  e.spin_torque = work(F[2], psi_dot);
  e.trail_lateral_force = work(-g.trail_m * F[1], psi_dot);
  e.offset_drag = work(-g.offset_m * F[0], psi_dot);
  e.torsional_damping = work(-g.torsional_damping_nms_per_rad * psi_dot, psi_dot);
  e.lateral_friction = work(F[3], y_dot);
  e.lateral_damping = work(-g.lateral_damping_ns_per_m * y_dot, y_dot);
  if (g.carcass_compliance()) {
    const double fx0 = contact_state(model, q.mode, q.t, q.x).force.Fx;
    e.carcass_lever = work(-(q.x[kCarcassY] * F[0] + fx0 * v[index_of(q, kCarcassY)]), psi_dot);
  }
  return e;
}

// The part of the energy the friction forces and torque do.
double friction_work(const EnergyPerCycle& e) {
  return e.spin_torque + e.trail_lateral_force + e.offset_drag + e.lateral_friction +
         e.carcass_lever;
}

// The dominant oscillatory mode (eigenvalue `ev`, eigenvector v): its growth and frequency, its
// kind (torsion, lateral, fore-aft) and its energy per cycle at 1 mrad or 1 mm, with the part
// the fall of friction with slip speed contributes.
void describe_dominant_mode(const GearModel& model, const QuasiSteadyState& q,
                            const Eigen::Matrix<double, 4, kStateSize>& Jc, std::complex<double> ev,
                            Eigen::VectorXcd v, StabilityReport& rep) {
  rep.growth_rate_per_s = ev.real();
  rep.frequency_hz = ev.imag() / (2 * std::numbers::pi);
  const std::complex<double> psi = v[index_of(q, kPsi)], y = v[index_of(q, kY)];
  rep.torsion_share = std::abs(psi) / (std::abs(psi) + std::abs(y) / 0.1);
  const int ix = index_of(q, kX);
  const double fore_aft = ix >= 0 ? std::abs(v[ix]) : 0.0;
  const double tire = longitudinal_deflection(q, v);
  rep.mode_kind = tire > std::max({std::abs(psi) * 1.0, std::abs(y), fore_aft}) ? "longitudinal"
                  : fore_aft > std::max(std::abs(psi) * 1.0, std::abs(y))
                      ? "fore-aft"
                      : (std::abs(psi) * 1.0 >= std::abs(y) ? "torsion" : "lateral");
  // Amplitude: 1 mrad of torsion or 1 mm of lateral or fore-aft deflection, whichever the mode
  // moves most (|psi| x 1 m against |y| and |x|, as mode_kind), so that a lateral mode's energy
  // is not that of a tiny torsion blown up to 1 mrad.
  const double largest = std::max({std::abs(psi) * 1.0, std::abs(y), fore_aft});
  v *= (largest > 1e-300 ? 1e-3 / largest : 1.0);
  rep.energy = mode_energy(model, q, Jc, v, ev.imag());
  // The fall of friction with slip speed: the same mode with f held at its operating value.
  GearModel flat = model;
  flat.config.tire.friction.static_coefficient = rep.friction;
  flat.config.tire.friction.kinetic_coefficient = rep.friction;
  rep.energy.fall_of_friction =
      friction_work(rep.energy) -
      friction_work(mode_energy(flat, q, contact_jacobian(flat, q), v, ev.imag()));
}

// The drag slope -dFx/dvx against the sliding speed the law reads (StabilityReport): through
// the wheel speed, vx = ... - Omega r, so -dFx/dvx = (dFx/dOmega) / r; with longitudinal
// relaxation the law reads V u / sigma_x, so -dFx/dvx = -(dFx/du) sigma_x / V. Both wheels.
double drag_slope(const GearModel& model, const Eigen::Matrix<double, 4, kStateSize>& Jc) {
  const double sigma_x = model.config.tire.longitudinal_relaxation_length_m;
  if (sigma_x > 0.0)
    return -(Jc(0, kSlipX) + Jc(0, kSlipX2)) * sigma_x / model.config.scenario.forward_speed_mps;
  return (Jc(0, kSpin) + Jc(0, kSpin2)) / model.config.structure.wheel_radius_m;
}

}  // namespace

StabilityReport assess_stability(const GearModel& model, StabilityPhase phase,
                                 const StabilityOptions& options) {
  StabilityReport rep;
  rep.state = quasi_steady_state(model, phase, options.touchdown_slip);
  const QuasiSteadyState& q = rep.state;
  const Eigen::MatrixXd A = linearise(model, q);
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, true);
  const int n = static_cast<int>(A.rows());
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) order[static_cast<std::size_t>(k)] = k;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return es.eigenvalues()[a].real() > es.eigenvalues()[b].real(); });
  for (int k : order) rep.eigenvalues.push_back(es.eigenvalues()[k]);
  rep.max_real_part = rep.eigenvalues.front().real();
  // The dominant oscillatory mode: above 0.5 Hz, largest real part.
  int dominant = -1;
  for (int k : order) {
    if (es.eigenvalues()[k].imag() > 2 * std::numbers::pi * 0.5) {
      dominant = k;
      break;
    }
  }
  const Eigen::Matrix<double, 4, kStateSize> Jc = contact_jacobian(model, q);
  rep.spin_torque_damping_nms_per_rad = -Jc(2, kPsiDot);
  rep.drag_slope_ns_per_m = drag_slope(model, Jc);
  rep.friction = contact_state(model, q.mode, q.t, q.x).friction;
  double best_share = -1.0;
  for (int k : order) {
    const std::complex<double> ev = es.eigenvalues()[k];
    if (ev.imag() <= 2 * std::numbers::pi * 0.5) continue;
    const Eigen::VectorXcd v = es.eigenvectors().col(k);
    // The torsion against the lateral and the tire's longitudinal deflection (1 mrad ~ 0.1 mm).
    const double psi = std::abs(v[index_of(q, kPsi)]);
    const double share =
        psi / (psi + (std::abs(v[index_of(q, kY)]) + longitudinal_deflection(q, v)) / 0.1);
    if (share > best_share) {
      best_share = share;
      rep.torsion_growth_rate_per_s = ev.real();
      rep.torsion_frequency_hz = ev.imag() / (2 * std::numbers::pi);
    }
  }
  if (dominant < 0)
    rep.growth_rate_per_s = rep.max_real_part;
  else
    describe_dominant_mode(model, q, Jc, es.eigenvalues()[dominant],
                           es.eigenvectors().col(dominant), rep);
  rep.perturbation_growth_rate_per_s = std::numeric_limits<double>::quiet_NaN();
  rep.perturbation_frequency_hz = std::numeric_limits<double>::quiet_NaN();
  if (options.simulate_perturbation && q.converged) {
    const OscillationEstimate e = perturbation_response(model, q, options);
    if (e.valid()) {
      rep.perturbation_growth_rate_per_s = e.growth_rate_per_s;
      rep.perturbation_frequency_hz = e.frequency_hz;
    }
  }
  return rep;
}

namespace {
constexpr std::array<double, 5> kTouchdownSlips{0.9, 0.7, 0.5, 0.3, 0.1};
}

StabilityReport assess_touchdown(const GearModel& model, const StabilityOptions& options) {
  if (model.contact == ContactModel::von_schlippe)
    return assess_stability(model, StabilityPhase::touchdown, options);
  StabilityOptions quick = options;
  quick.simulate_perturbation = false;
  double worst_slip = kTouchdownSlips.front(), worst = -std::numeric_limits<double>::infinity();
  for (double s : kTouchdownSlips) {
    quick.touchdown_slip = s;
    const StabilityReport r = assess_stability(model, StabilityPhase::touchdown, quick);
    if (r.state.converged && r.growth_rate_per_s > worst) {
      worst = r.growth_rate_per_s;
      worst_slip = s;
    }
  }
  StabilityOptions o = options;
  o.touchdown_slip = worst_slip;
  return assess_stability(model, StabilityPhase::touchdown, o);
}

double linear_growth_rate(const GearModel& model, StabilityPhase phase) {
  StabilityOptions o;
  o.simulate_perturbation = false;
  const StabilityReport r = phase == StabilityPhase::touchdown ? assess_touchdown(model, o)
                                                               : assess_stability(model, phase, o);
  return r.state.converged ? r.growth_rate_per_s : std::numeric_limits<double>::quiet_NaN();
}

double classical_critical_damping(const GearModel& model_in) {
  GearModel model = model_in;
  model.contact = ContactModel::von_schlippe;
  model.exact.reset();
  const auto unstable = [&](double c) {
    model.config.structure.torsional_damping_nms_per_rad = c;
    const QuasiSteadyState q = quasi_steady_state(model, StabilityPhase::touchdown);
    const Eigen::MatrixXd A = linearise(model, q);
    return Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues().real().maxCoeff() > 0.0;
  };
  if (!unstable(0.0)) return 0.0;
  double lo = 0.0, hi = 1000.0;
  while (unstable(hi)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e8) throw std::runtime_error("classical_critical_damping: no stable damping found");
  }
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (unstable(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace contensou
