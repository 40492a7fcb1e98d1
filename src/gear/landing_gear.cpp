#include "contensou/gear/landing_gear.hpp"

#include "gear_internals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>
#include <utility>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/pressure_profile.hpp"

namespace contensou {

const char* to_string(ContactModel model) {
  switch (model) {
    case ContactModel::coupled:
      return "coupled";
    case ContactModel::decoupled:
      return "decoupled";
    case ContactModel::von_schlippe:
      return "von_schlippe";
  }
  return "?";
}

ContactModel contact_model_from_string(const std::string& name) {
  for (ContactModel m :
       {ContactModel::coupled, ContactModel::decoupled, ContactModel::von_schlippe})
    if (name == to_string(m)) return m;
  if (name == "nonholonomic") return ContactModel::von_schlippe;  // the former name
  throw InvalidArgument("contact model", name,
                        "must be coupled, decoupled or von_schlippe (alias nonholonomic)");
}

namespace detail {

ContactPatch unit_patch(const SlidingTire& tire) {
  ContactPatch p;
  p.radius_m = 1.0;
  p.reference_pressure_pa = 1.0;
  p.friction = 1.0;
  p.profile = seed_tire_profile();
  p.profile.kx = tire.rolling_shift;
  return p;
}

// S(x) = x^2 (3 - 2x) on [0, 1]: C1 at both ends.
double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace detail

using namespace detail;

GearModel make_gear_model(const GearConfig& config, ContactModel contact) {
  validate(config);
  GearModel m;
  m.config = config;
  m.contact = contact;
  const ContactPatch patch = unit_patch(config.tire);
  m.moment_1 = moment(patch.profile, 1);
  m.moment_ratio_2 = moment(patch.profile, 2) / m.moment_1;
  m.moment_ratio_3 = moment(patch.profile, 3) / m.moment_1;
  const std::string& which = config.tire.law_coefficients;
  const FractionalLaw<double> law =
      which == "fitted" ? fractional_law_fitted(patch) : fractional_law_from_patch(patch);
  m.law_a = which == "seed" ? 1.03 : law.a;  // seed Table 3
  m.law_m = which == "seed" ? 1.72 : law.m;
  m.law_c = law.c;
  m.law_a_k = law.a_k;
  if (config.tire.exact_integrals && contact == ContactModel::coupled)
    m.exact = std::make_shared<const ExactLaw>(make_exact_law(make_exact_model(patch, 1e-10)));
  return m;
}

double vertical_load(const LandingScenario& s, double t) {
  return s.static_load_n * smoothstep((t - s.touchdown_time_s) / s.load_ramp_s);
}

GearState initial_state(const GearModel& model) {
  GearState x = GearState::Zero();
  x[kPsi] = model.config.scenario.initial_torsion_rad;
  x[kY] = model.config.scenario.initial_lateral_m;
  // Every model touches down with the wheel at rest: the string tire too slides (on its friction
  // circle) until the wheel has spun up, like for like with the dry-friction models.
  return x;
}

GearMode initial_mode(const GearModel& model) {
  GearMode mode;
  mode.loaded = model.config.scenario.touchdown_time_s <= 0.0;
  mode.rolling = model.contact == ContactModel::von_schlippe;
  const LandingScenario& s = model.config.scenario;
  mode.brake_command = s.braking && s.brake_on_s <= 0.0;
  return mode;
}

namespace detail {

// The vector fractional law of the coupled model at load N, patch radius R and friction f:
// F0 = f N, M0 = f N R A^2/A^1, Mk = f N R A^3 / (2 A^1) (theory.md section 4).
FractionalLaw<double> coupled_law(const GearModel& model, double N, double R, double f) {
  const SlidingTire& tire = model.config.tire;
  FractionalLaw<double> law;
  law.F0 = f * N;
  law.M0 = f * N * R * model.moment_ratio_2;
  law.Mk = 0.5 * f * N * R * model.moment_ratio_3;
  law.a = model.law_a;
  law.m = model.law_m;
  law.c = model.law_c;
  law.a_k = model.law_a_k;
  law.kx = tire.rolling_shift;
  law.ky = 0.0;
  law.kappa = 1.0;
  law.radius = R;
  law.regularization_speed = tire.regularization_speed;
  return law;
}

// Sliding friction on the tire from the chosen law at load N, patch radius R and friction f.
Resultants<double> sliding_friction(const GearModel& model, const Kinematics<double>& k, double N,
                                    double R, double f) {
  const SlidingTire& tire = model.config.tire;
  const double eps = tire.regularization_speed;
  if (model.contact == ContactModel::decoupled) {
    // Coulomb force along -v and Coulomb spin torque M0 (1 + kappa)/2, kappa = 1, each
    // regularised by eps.
    const double v = std::sqrt(k.vx * k.vx + k.vy * k.vy + eps * eps);
    const double u = k.omega * R;
    const double M0 = f * N * R * model.moment_ratio_2;
    return {-f * N * k.vx / v, -f * N * k.vy / v, -M0 * u / std::sqrt(u * u + eps * eps)};
  }
  if (model.exact) {
    // Unit patch: forces scale with f p* R^2 = f N / L, the torque with one more R.
    const double scale = f * N / model.exact->load_area;
    const Resultants<double> r =
        exact_law_resultants(*model.exact, Kinematics<double>{k.vx, k.vy, k.omega * R});
    return {scale * r.Fx, scale * r.Fy, scale * R * r.Mz};
  }
  return fractional_resultants(coupled_law(model, N, R, f), k);
}

// The coupled sliding law (fractional, or the exact law scaled from the unit patch) with its
// analytic Jacobian d(Fx, Fy, Mz)/d(vx, vy, omega) at fixed load, patch radius and friction f.
FractionalWithJacobian coupled_law_with_jacobian(const GearModel& model,
                                                 const Kinematics<double>& k, double N, double R,
                                                 double f) {
  if (!model.exact) return fractional_resultants_with_jacobian(coupled_law(model, N, R, f), k);
  const double scale = f * N / model.exact->load_area;
  const ExactLawWithJacobian r =
      exact_law_resultants_with_jacobian(*model.exact, Kinematics<double>{k.vx, k.vy, k.omega * R});
  FractionalWithJacobian out;
  out.resultants = {scale * r.resultants.Fx, scale * r.resultants.Fy, scale * R * r.resultants.Mz};
  out.jacobian = r.jacobian;
  out.jacobian.col(2) *= R;  // d/domega = R d/d(omega R)
  out.jacobian.topRows<2>() *= scale;
  out.jacobian.row(2) *= scale * R;
  return out;
}

// The torsional spring's deflection d(psi) across the torque-link freeplay and its slope
// (landing_gear.hpp, GearStructure::freeplay_rad).
std::pair<double, double> freeplay_deflection(double psi, double delta) {
  if (!(delta > 0.0)) return {psi, 1.0};
  const double s = delta / 20.0;
  const double a = psi - delta, b = psi + delta;
  const double ra = std::sqrt(a * a + s * s), rb = std::sqrt(b * b + s * s);
  return {0.5 * (a + ra) + 0.5 * (b - rb), 0.5 * (1.0 + a / ra) + 0.5 * (1.0 - b / rb)};
}

// g = I_w Omega / L, zero without a gyroscopic length.
double gyroscopic_coefficient(const GearStructure& g, double spin) {
  return g.gyroscopic_length_m > 0.0 ? g.wheel_inertia_kgm2 * spin / g.gyroscopic_length_m : 0.0;
}

// Effective slip speed of the sliding patch, (v^2 + (2 u / 3)^2)^(1/2): the mean local slip
// speed's two limits (docs/shimmy.md); f(w) of SlipSpeedFriction.
double sliding_slip_speed(const Kinematics<double>& k, double R) {
  const double u = k.omega * R;
  return std::sqrt(k.vx * k.vx + k.vy * k.vy + 4.0 / 9.0 * u * u);
}

// df/dw of f(w) = f_k + (f_s - f_k) exp(-(w / w_s)^delta).
double friction_slope(const SlipSpeedFriction<double>& law, double w) {
  if (!(w > 0.0)) return 0.0;
  const double z = w / law.reference_speed;
  const double zd = std::pow(z, law.exponent);
  return -(law.static_coefficient - law.kinetic_coefficient) * std::exp(-zd) * law.exponent * zd /
         w;
}

// deflection lambda, at cs.load_n > 0 and cs.patch_radius_m; fills cs.force and cs.friction.
void contact_forces(const GearModel& model, bool rolling, double lambda, ContactState& cs) {
  const GearConfig& c = model.config;
  const double N = cs.load_n, R = cs.patch_radius_m;
  if (rolling) {
    rolling_forces(c, lambda, cs);
    return;
  }
  cs.friction = friction_at(c.tire.friction, sliding_slip_speed(cs.slip, R));
  cs.force = sliding_friction(model, cs.slip, N, R, cs.friction);
}

// K = d(Fx, Fy, Mz)/d(vx, vy, omega) of the sliding law at fixed load and patch radius (w.force
// and w.friction filled): analytic for the coupled law (fractional or exact), F = f(w) G(v,
// omega), the law's Jacobian at fixed f plus G f'(w) grad w; forward differences of the law
// (one evaluation per input) otherwise.
Eigen::Matrix3d sliding_law_jacobian(const GearModel& model, const ContactState& w) {
  Eigen::Matrix3d K;
  if (model.contact == ContactModel::coupled) {
    const double R = w.patch_radius_m;
    const FractionalWithJacobian law =
        coupled_law_with_jacobian(model, w.slip, w.load_n, R, w.friction);
    K = law.jacobian;
    const double speed = sliding_slip_speed(w.slip, R);
    if (speed > 0.0) {
      const double slope = friction_slope(model.config.tire.friction, speed) / w.friction;
      const Eigen::Vector3d grad_w(w.slip.vx / speed, w.slip.vy / speed,
                                   4.0 / 9.0 * w.slip.omega * R * R / speed);
      const Eigen::Vector3d F(law.resultants.Fx, law.resultants.Fy, law.resultants.Mz);
      K += slope * F * grad_w.transpose();
    }
    return K;
  }
  const Eigen::Vector3d F0(w.force.Fx, w.force.Fy, w.force.Mz);
  for (int j = 0; j < 3; ++j) {
    ContactState p = w;
    double* v = j == 0 ? &p.slip.vx : j == 1 ? &p.slip.vy : &p.slip.omega;
    const double h = 1e-7 * std::max(std::abs(*v), 1.0);
    *v += h;
    contact_forces(model, false, 0.0, p);
    K.col(j) = (Eigen::Vector3d(p.force.Fx, p.force.Fy, p.force.Mz) - F0) / h;
  }
  return K;
}

// The massless patch on the compliant carcass (landing_gear.hpp, GearStructure::carcass_*;
// docs/shimmy.md, "Carcass compliance"). Given the rim's patch kinematics in cs.slip and the
// carcass deflections e_y, e_psi, find the patch's rates z = (e_y', e_psi') relative to the rim
// such that the friction on the patch balances the carcass (Pacejka 2012, sec. 7.2: a massless
// contact point on a lateral spring-damper; Besselink 2000, ch. 3, the same in torsion):
//   r_1(z) = Fy(vx - e_y psi', vy + z_1, omega + z_2) - k_cy e_y - c_cy z_1 = 0
//   r_2(z) = Mz(vx - e_y psi', vy + z_1, omega + z_2) - k_cpsi e_psi - c_cpsi z_2 = 0
// by Newton's method with the law's Jacobian (dr/dz = K - diag(c_cy, c_cpsi), K the sliding
// law's partials) and step halving. The patch's yaw e_psi turns its frame against the rim's; for
// the isotropic law (kappa = 1) that changes the force only through the tread-aligned pressure
// shift kx, O(kx e_psi), which is neglected: forces stay in the rim's frame. Fills cs.slip with
// the patch's kinematics, cs.force, cs.friction and cs.carcass_rate.
void carcass_contact(const GearModel& model, double psi_rate, double e_y, double e_psi,
                     ContactState& cs) {
  const GearStructure& g = model.config.structure;
  const Kinematics<double> rim = cs.slip;
  const double ky = g.carcass_lateral_stiffness_n_per_m, cy = g.carcass_lateral_damping_ns_per_m;
  const double kp = g.carcass_torsional_stiffness_nm_per_rad;
  const double cpsi = g.carcass_torsional_damping_nms_per_rad;
  const auto evaluate = [&](const Eigen::Vector2d& z, ContactState& p) {
    p = cs;
    p.slip.vx = rim.vx - e_y * psi_rate;  // the patch centre sits e_y further out on the lever
    p.slip.vy = rim.vy + z[0];
    p.slip.omega = rim.omega + z[1];
    contact_forces(model, false, 0.0, p);
    return Eigen::Vector2d(p.force.Fy - ky * e_y - cy * z[0],
                           p.force.Mz - kp * e_psi - cpsi * z[1]);
  };
  // Residual scales: the force and torque levels of the law.
  const double fscale = std::max(cs.friction > 0.0 ? cs.friction : 1.0, 1e-3) * cs.load_n + 1e-6;
  const Eigen::Vector2d scale(1.0 / fscale, 1.0 / (fscale * cs.patch_radius_m));
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  ContactState p;
  Eigen::Vector2d r = evaluate(z, p);
  for (int iter = 0; iter < 60; ++iter) {
    const double norm = r.cwiseProduct(scale).lpNorm<Eigen::Infinity>();
    if (!(norm > 1e-15)) break;
    const Eigen::Matrix3d K = sliding_law_jacobian(model, p);
    // dr/dz = [[K_yy - c_cy, K_yw], [K_My, K_Mw - c_cpsi]], solved by Cramer's rule.
    const double a11 = K(1, 1) - cy, a12 = K(1, 2), a21 = K(2, 1), a22 = K(2, 2) - cpsi;
    const double det = a11 * a22 - a12 * a21;
    const Eigen::Vector2d step(-(a22 * r[0] - a12 * r[1]) / det, -(a11 * r[1] - a21 * r[0]) / det);
    if (!step.allFinite()) break;
    double lambda = 1.0;
    Eigen::Vector2d zt = z, rt = r;
    ContactState pt;
    for (int halving = 0; halving < 40; ++halving, lambda *= 0.5) {
      zt = z + lambda * step;
      rt = evaluate(zt, pt);
      if (rt.cwiseProduct(scale).lpNorm<Eigen::Infinity>() < norm) break;
    }
    if (!(rt.cwiseProduct(scale).lpNorm<Eigen::Infinity>() < norm)) break;  // at rounding level
    z = zt;
    r = rt;
    p = pt;
  }
  cs = p;
  cs.carcass_rate = {z[0], z[1]};
}

}  // namespace detail

namespace detail {

// The wheels of the gear (landing_gear.hpp, GearStructure::wheel_spacing_m): one at the offset
// l, or two at l + b/2 and l - b/2 that share the load; each with its patch kinematics, load,
// patch radius, anti-skid brake torque and friction. Returns the number of wheels.
int wheel_contacts(const GearModel& model, const GearMode& mode, double t, const GearState& x,
                   std::array<WheelContact, 2>& wheels) {
  const GearConfig& c = model.config;
  const GearStructure& g = c.structure;
  const LandingScenario& s = c.scenario;
  const double V = s.forward_speed_mps;
  const double cp = std::cos(x[kPsi]), sp = std::sin(x[kPsi]);
  const double lateral = x[kYDot] + s.drift_speed_mps;
  const int n = g.wheel_spacing_m > 0.0 ? 2 : 1;
  const double load = mode.loaded ? vertical_load(s, t) / n : 0.0;
  // R = sqrt(N / (2 pi p* A^1)), floored so that the law stays defined at zero load.
  const auto radius = [&](double N) {
    return std::sqrt(N / (2.0 * std::numbers::pi * c.tire.inflation_pressure_pa * model.moment_1));
  };
  // The wheel's ground speed along X is V + x' (fore-aft bending; x' = 0 when it is off).
  const double forward = V + x[kXDot];
  for (int i = 0; i < n; ++i) {
    WheelContact& w = wheels[static_cast<std::size_t>(i)];
    w = WheelContact{};
    w.offset = n == 1 ? g.offset_m : g.offset_m + (i == 0 ? 0.5 : -0.5) * g.wheel_spacing_m;
    w.spin = i == 0 ? kSpin : kSpin2;
    ContactState& cs = w.cs;
    cs.slip.vx = forward * cp + lateral * sp - w.offset * x[kPsiDot] - x[w.spin] * g.wheel_radius_m;
    // Longitudinal relaxation (SlidingTire::longitudinal_relaxation_length_m): the laws see the
    // relaxed V u / sigma_x; u relaxes towards sigma_x vx / V while loaded.
    const double sigma_x = c.tire.longitudinal_relaxation_length_m;
    if (sigma_x > 0.0) {
      const double u = x[i == 0 ? kSlipX : kSlipX2];
      const double relaxed = V * u / sigma_x;
      if (mode.loaded) cs.longitudinal_rate[0] = cs.slip.vx - relaxed;
      cs.slip.vx = relaxed;
    }
    cs.slip.vy = -forward * sp + lateral * cp - g.trail_m * x[kPsiDot];
    cs.slip.omega = x[kPsiDot];
    cs.slip_ratio = cs.slip.vx / V;
    cs.load_n = load;
    cs.patch_radius_m = std::max(radius(load), 1e-3 * radius(s.static_load_n / n));
    // Anti-skid: the brake sees the wheel-speed slip 1 - Omega r / V (a wheel tachometer),
    // not the patch's sliding, which also carries -l psi' / V.
    if (mode.brake_command) {
      const double wheel_slip = 1.0 - x[w.spin] * g.wheel_radius_m / V;
      const double z = (wheel_slip - s.brake_target_slip) / s.brake_slip_band;
      cs.brake_torque_nm = s.brake_max_torque_nm / (1.0 + std::exp(std::clamp(z, -50.0, 50.0)));
    }
    if (load > 0.0) {
      if (!mode.rolling && g.carcass_compliance())
        carcass_contact(model, x[kPsiDot], x[kCarcassY], x[kCarcassPsi], cs);
      else
        contact_forces(model, mode.rolling, x[kLambda], cs);
    }
  }
  return n;
}

}  // namespace detail

ContactState contact_state(const GearModel& model, const GearMode& mode, double t,
                           const GearState& x) {
  std::array<WheelContact, 2> wheels;
  const int n = wheel_contacts(model, mode, t, x, wheels);
  if (n == 1) {
    ContactState cs = wheels[0].cs;
    cs.wheel_fx_n = {cs.force.Fx, 0.0};
    cs.wheel_brake_nm = {cs.brake_torque_nm, 0.0};
    return cs;
  }
  // Twin: the mean kinematics and friction, the summed load and forces, the moment about the
  // midpoint between the patches, sum (Mz_i - (l_i - l) Fx_i); the patch radius of one wheel.
  ContactState cs = wheels[0].cs;
  const ContactState& b = wheels[1].cs;
  cs.slip.vx = 0.5 * (cs.slip.vx + b.slip.vx);
  cs.slip_ratio = 0.5 * (cs.slip_ratio + b.slip_ratio);
  cs.friction = 0.5 * (cs.friction + b.friction);
  cs.load_n += b.load_n;
  const double l = model.config.structure.offset_m;
  cs.force.Mz = cs.force.Mz - (wheels[0].offset - l) * cs.force.Fx + b.force.Mz -
                (wheels[1].offset - l) * b.force.Fx;
  cs.wheel_fx_n = {cs.force.Fx, b.force.Fx};
  cs.longitudinal_rate[1] = b.longitudinal_rate[0];
  cs.wheel_brake_nm = {cs.brake_torque_nm, b.brake_torque_nm};
  cs.force.Fx += b.force.Fx;
  cs.force.Fy += b.force.Fy;
  cs.brake_torque_nm += b.brake_torque_nm;
  return cs;
}

GearState gear_rhs(const GearModel& model, const GearMode& mode, double t, const GearState& x) {
  const GearStructure& g = model.config.structure;
  const LandingScenario& s = model.config.scenario;
  const ContactState cs = contact_state(model, mode, t, x);
  const Resultants<double>& F = cs.force;
  const double cp = std::cos(x[kPsi]), sp = std::sin(x[kPsi]);
  GearState dx;
  // Gyroscopic coupling g = I_w Omega / L (landing_gear.hpp, GearStructure).
  const double gyro = gyroscopic_coefficient(g, x[kSpin] + x[kSpin2]);  // both wheels' spin
  dx[kY] = x[kYDot];
  dx[kYDot] = (-g.lateral_stiffness_n_per_m * x[kY] - g.lateral_damping_ns_per_m * x[kYDot] +
               F.Fx * sp + F.Fy * cp + gyro * x[kPsiDot]) /
              g.lateral_mass_kg;
  dx[kPsi] = x[kPsiDot];
  dx[kPsiDot] =
      (-g.torsional_stiffness_nm_per_rad * freeplay_deflection(x[kPsi], g.freeplay_rad).first -
       g.torsional_damping_nms_per_rad * x[kPsiDot] + F.Mz - g.trail_m * F.Fy -
       (g.offset_m + (g.carcass_compliance() ? x[kCarcassY] : 0.0)) * F.Fx - gyro * x[kYDot]) /
      g.torsional_inertia_kgm2;
  // The brake torque opposes the spin; tanh(Omega / 1 rad/s) keeps it smooth through zero.
  dx[kSpin] = (-g.wheel_radius_m * cs.wheel_fx_n[0] - cs.wheel_brake_nm[0] * std::tanh(x[kSpin])) /
              g.wheel_inertia_kgm2;
  // The second wheel of a twin gear (inert for one wheel).
  dx[kSpin2] =
      g.wheel_spacing_m > 0.0
          ? (-g.wheel_radius_m * cs.wheel_fx_n[1] - cs.wheel_brake_nm[1] * std::tanh(x[kSpin2])) /
                g.wheel_inertia_kgm2
          : 0.0;
  // Stretched string (Somieski 1997): the leading point, a = R ahead of the patch centre,
  // does not slide; lambda relaxes over the relaxation length.
  if (mode.rolling && mode.loaded) {
    const double V = s.forward_speed_mps;
    dx[kLambda] = -(cs.slip.vy + cs.patch_radius_m * x[kPsiDot]) -
                  V / model.config.rolling.relaxation_length_m * x[kLambda];
  } else {
    dx[kLambda] = 0.0;
  }
  // Fore-aft bending: the force at the patch along X, (Fx cos psi - Fy sin psi).
  if (g.fore_aft_stiffness_n_per_m > 0.0) {
    dx[kX] = x[kXDot];
    dx[kXDot] = (-g.fore_aft_stiffness_n_per_m * x[kX] - g.fore_aft_damping_ns_per_m * x[kXDot] +
                 F.Fx * cp - F.Fy * sp) /
                g.fore_aft_mass_kg;
  } else {
    dx[kX] = dx[kXDot] = 0.0;
  }
  // Carcass compliance (GearStructure::carcass_*): sliding, the patch's rates from the force
  // balance (carcass_contact); rolling or airborne, the stretched string is the carcass (its
  // lambda carries the lateral force), so e_y, e_psi relax unloaded, k e + c e' = 0.
  if (g.carcass_compliance()) {
    if (mode.loaded && !mode.rolling && cs.load_n > 0.0) {
      dx[kCarcassY] = cs.carcass_rate[0];
      dx[kCarcassPsi] = cs.carcass_rate[1];
    } else {
      dx[kCarcassY] =
          -g.carcass_lateral_stiffness_n_per_m / g.carcass_lateral_damping_ns_per_m * x[kCarcassY];
      dx[kCarcassPsi] = -g.carcass_torsional_stiffness_nm_per_rad /
                        g.carcass_torsional_damping_nms_per_rad * x[kCarcassPsi];
    }
  } else {
    dx[kCarcassY] = dx[kCarcassPsi] = 0.0;
  }
  // Longitudinal relaxation: u_i' = vx_i - (V / sigma_x) u_i while loaded (wheel_contacts).
  dx[kSlipX] = cs.longitudinal_rate[0];
  dx[kSlipX2] = cs.longitudinal_rate[1];
  return dx;
}

GearConfig legacy_gear_config() {
  GearConfig c;
  c.structure.torsional_damping_nms_per_rad = 100.0;
  return c;
}

GearConfig gear_config_by_name(const std::string& name) {
  if (name == "default") return GearConfig{};
  if (name == "legacy") return legacy_gear_config();
  throw InvalidArgument("gear", name, "must be default or legacy");
}

}  // namespace contensou
