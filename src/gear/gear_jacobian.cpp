// The structured Jacobian d(dx/dt)/dx of the landing gear (landing_gear.hpp, gear_jacobian).
#include "contensou/gear/landing_gear.hpp"

#include "gear_internals.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace contensou {

using namespace detail;

namespace {

// d(dx/dt)/dx by forward differences of gear_rhs, one evaluation per state (carcass compliance:
// e_y', e_psi' come from an implicit solve).
GearJacobian jacobian_by_differences(const GearModel& model, const GearMode& mode, double t,
                                     const GearState& x) {
  const GearState f0 = gear_rhs(model, mode, t, x);
  GearJacobian J;
  for (int j = 0; j < kStateSize; ++j) {
    GearState xp = x;
    const double h = 1e-7 * std::max(std::abs(x[j]), kStateScale[static_cast<std::size_t>(j)]);
    xp[j] += h;
    J.col(j) = (gear_rhs(model, mode, t, xp) - f0) / h;
  }
  return J;
}

using KinematicsJacobian = Eigen::Matrix<double, 4, kStateSize>;

// d(vx, vy, omega, lambda)/dx of the patch kinematics (landing_gear.hpp; theory.md section 1),
// without the wheel's own columns (offset l_i on psi', spin Omega_i), which wheel_kinematics adds.
KinematicsJacobian kinematics_jacobian(const GearModel& model, const GearState& x) {
  const LandingScenario& s = model.config.scenario;
  const double cp = std::cos(x[kPsi]), sp = std::sin(x[kPsi]);
  const double lateral = x[kYDot] + s.drift_speed_mps;
  const double forward = s.forward_speed_mps + x[kXDot];
  KinematicsJacobian D = KinematicsJacobian::Zero();
  D(0, kYDot) = sp;
  D(0, kPsi) = -forward * sp + lateral * cp;
  D(0, kXDot) = cp;
  D(1, kYDot) = cp;
  D(1, kPsi) = -forward * cp - lateral * sp;
  D(1, kXDot) = -sp;
  D(1, kPsiDot) = -model.config.structure.trail_m;
  D(2, kPsiDot) = 1.0;
  D(3, kLambda) = 1.0;
  return D;
}

// K = d(Fx, Fy, Mz)/d(vx, vy, omega, lambda) of one wheel's contact law at fixed load and patch:
// analytic for the sliding coupled law, forward differences of the law in its inputs (one
// evaluation each) for the others; zero without load.
Eigen::Matrix<double, 3, 4> contact_law_jacobian(const GearModel& model, const GearMode& mode,
                                                 const GearState& x, const ContactState& w) {
  Eigen::Matrix<double, 3, 4> K = Eigen::Matrix<double, 3, 4>::Zero();
  if (!(w.load_n > 0.0)) return K;
  if (!mode.rolling && model.contact == ContactModel::coupled) {
    K.leftCols<3>() = sliding_law_jacobian(model, w);
    return K;
  }
  const double V = model.config.scenario.forward_speed_mps;
  const Eigen::Vector3d F0(w.force.Fx, w.force.Fy, w.force.Mz);
  const int inputs = mode.rolling ? 4 : 3;
  for (int j = 0; j < inputs; ++j) {
    ContactState p = w;
    double lambda = x[kLambda];
    double* v = j == 0 ? &p.slip.vx : j == 1 ? &p.slip.vy : j == 2 ? &p.slip.omega : &lambda;
    const double h =
        j == 3 ? 1e-7 * std::max(std::abs(lambda), 1e-3) : 1e-7 * std::max(std::abs(*v), 1.0);
    *v += h;
    p.slip_ratio = p.slip.vx / V;
    contact_forces(model, mode.rolling, lambda, p);
    K.col(j) = (Eigen::Vector3d(p.force.Fx, p.force.Fy, p.force.Mz) - F0) / h;
  }
  return K;
}

// The friction's partials in the state: rows Fx, Fy, Mz of the gear's resultant (the moment
// about the midpoint for a twin), and each wheel's drag.
struct FrictionJacobian {
  Eigen::Matrix<double, 3, kStateSize> resultant = Eigen::Matrix<double, 3, kStateSize>::Zero();
  std::array<Eigen::Matrix<double, 1, kStateSize>, 2> wheel_drag{};
  // With longitudinal relaxation: each wheel's kinematic dvx/dx (the row of its u').
  std::array<Eigen::Matrix<double, 1, kStateSize>, 2> kinematic_vx{};
};

FrictionJacobian friction_jacobian(const GearModel& model, const GearMode& mode, const GearState& x,
                                   const KinematicsJacobian& D,
                                   const std::array<WheelContact, 2>& wheels, int n) {
  const GearStructure& g = model.config.structure;
  FrictionJacobian out;
  Eigen::Matrix<double, 3, kStateSize>& dF = out.resultant;
  for (int i = 0; i < n; ++i) {
    const WheelContact& wc = wheels[static_cast<std::size_t>(i)];
    const Eigen::Matrix<double, 3, 4> K = contact_law_jacobian(model, mode, x, wc.cs);
    KinematicsJacobian Di = D;
    Di(0, kPsiDot) = -wc.offset;
    Di(0, wc.spin) = -g.wheel_radius_m;
    const double sigma_x = model.config.tire.longitudinal_relaxation_length_m;
    if (sigma_x > 0.0) {  // the law sees V u_i / sigma_x (landing_gear.hpp, SlidingTire)
      out.kinematic_vx[static_cast<std::size_t>(i)] = Di.row(0);
      Di.row(0).setZero();
      Di(0, i == 0 ? kSlipX : kSlipX2) = model.config.scenario.forward_speed_mps / sigma_x;
    }
    const Eigen::Matrix<double, 3, kStateSize> dFi = K * Di;
    out.wheel_drag[static_cast<std::size_t>(i)] = dFi.row(0);
    dF.row(0) += dFi.row(0);
    dF.row(1) += dFi.row(1);
    dF.row(2) += dFi.row(2) - (n == 1 ? 0.0 : wc.offset - g.offset_m) * dFi.row(0);
  }
  return out;
}

// The strut's rows: lateral bending and torsion (landing_gear.hpp, equations of motion).
void strut_rows(const GearModel& model, const GearState& x, const Resultants<double>& F,
                const FrictionJacobian& dF, GearJacobian& J) {
  const GearStructure& g = model.config.structure;
  const double cp = std::cos(x[kPsi]), sp = std::sin(x[kPsi]);
  const Eigen::Matrix<double, 3, kStateSize>& dR = dF.resultant;
  J(kY, kYDot) = 1.0;
  J.row(kYDot) = (dR.row(0) * sp + dR.row(1) * cp) / g.lateral_mass_kg;
  J(kYDot, kPsi) += (F.Fx * cp - F.Fy * sp) / g.lateral_mass_kg;
  J(kYDot, kY) -= g.lateral_stiffness_n_per_m / g.lateral_mass_kg;
  J(kYDot, kYDot) -= g.lateral_damping_ns_per_m / g.lateral_mass_kg;
  J(kPsi, kPsiDot) = 1.0;
  J.row(kPsiDot) =
      (dR.row(2) - g.trail_m * dR.row(1) - g.offset_m * dR.row(0)) / g.torsional_inertia_kgm2;
  J(kPsiDot, kPsi) -= g.torsional_stiffness_nm_per_rad *
                      freeplay_deflection(x[kPsi], g.freeplay_rad).second /
                      g.torsional_inertia_kgm2;
  J(kPsiDot, kPsiDot) -= g.torsional_damping_nms_per_rad / g.torsional_inertia_kgm2;
}

// Each wheel's row: I_w Omega_i' = -r Fx_i - T_i(Omega_i) tanh(Omega_i), with
// T = T_max / (1 + e^z), z = (1 - Omega r / V - s*) / ds.
void wheel_rows(const GearModel& model, const GearMode& mode, const GearState& x,
                const std::array<WheelContact, 2>& wheels, int n, const FrictionJacobian& dF,
                GearJacobian& J) {
  const GearStructure& g = model.config.structure;
  const LandingScenario& s = model.config.scenario;
  const double V = s.forward_speed_mps, r = g.wheel_radius_m;
  for (int i = 0; i < n; ++i) {
    const WheelContact& wc = wheels[static_cast<std::size_t>(i)];
    J.row(wc.spin) = -r * dF.wheel_drag[static_cast<std::size_t>(i)] / g.wheel_inertia_kgm2;
    const double th = std::tanh(x[wc.spin]);
    double dT = 0.0;
    if (mode.brake_command) {
      const double z = (1.0 - x[wc.spin] * r / V - s.brake_target_slip) / s.brake_slip_band;
      if (std::abs(z) < 50.0) {
        const double ez = std::exp(z);
        dT = s.brake_max_torque_nm * ez / ((1.0 + ez) * (1.0 + ez)) * r / (V * s.brake_slip_band);
      }
    }
    J(wc.spin, wc.spin) -=
        (dT * th + wc.cs.brake_torque_nm * (1.0 - th * th)) / g.wheel_inertia_kgm2;
  }
}

// The optional degrees of freedom and couplings: fore-aft bending, gyroscopic coupling, the
// longitudinal relaxation and the stretched string while rolling.
void optional_rows(const GearModel& model, const GearMode& mode, const GearState& x,
                   const ContactState& cs, const KinematicsJacobian& D, const FrictionJacobian& dF,
                   GearJacobian& J) {
  const GearStructure& g = model.config.structure;
  const double cp = std::cos(x[kPsi]), sp = std::sin(x[kPsi]);
  const Resultants<double>& F = cs.force;
  if (g.fore_aft_stiffness_n_per_m > 0.0) {
    const Eigen::Matrix<double, 3, kStateSize>& dR = dF.resultant;
    J(kX, kXDot) = 1.0;
    J.row(kXDot) = (dR.row(0) * cp - dR.row(1) * sp) / g.fore_aft_mass_kg;
    J(kXDot, kPsi) += (-F.Fx * sp - F.Fy * cp) / g.fore_aft_mass_kg;
    J(kXDot, kX) -= g.fore_aft_stiffness_n_per_m / g.fore_aft_mass_kg;
    J(kXDot, kXDot) -= g.fore_aft_damping_ns_per_m / g.fore_aft_mass_kg;
  }
  if (g.gyroscopic_length_m > 0.0) {
    const double gyro = gyroscopic_coefficient(g, x[kSpin] + x[kSpin2]);
    const double dgyro = g.wheel_inertia_kgm2 / g.gyroscopic_length_m;  // d g / d Omega_i
    J(kYDot, kPsiDot) += gyro / g.lateral_mass_kg;
    J(kPsiDot, kYDot) -= gyro / g.torsional_inertia_kgm2;
    for (int spin : {static_cast<int>(kSpin), static_cast<int>(kSpin2)}) {
      J(kYDot, spin) += dgyro * x[kPsiDot] / g.lateral_mass_kg;
      J(kPsiDot, spin) -= dgyro * x[kYDot] / g.torsional_inertia_kgm2;
    }
  }
  const double sigma_x = model.config.tire.longitudinal_relaxation_length_m;
  if (sigma_x > 0.0 && mode.loaded) {
    const double rate = model.config.scenario.forward_speed_mps / sigma_x;
    J.row(kSlipX) = dF.kinematic_vx[0];
    J(kSlipX, kSlipX) -= rate;
    if (g.wheel_spacing_m > 0.0) {
      J.row(kSlipX2) = dF.kinematic_vx[1];
      J(kSlipX2, kSlipX2) -= rate;
    }
  }
  if (mode.rolling && mode.loaded) {
    J.row(kLambda) = -D.row(1);
    J(kLambda, kPsiDot) -= cs.patch_radius_m;
    J(kLambda, kLambda) -=
        model.config.scenario.forward_speed_mps / model.config.rolling.relaxation_length_m;
  }
}

}  // namespace

GearJacobian gear_jacobian(const GearModel& model, const GearMode& mode, double t,
                           const GearState& x) {
  if (model.config.structure.carcass_compliance())
    return jacobian_by_differences(model, mode, t, x);
  const ContactState cs = contact_state(model, mode, t, x);
  std::array<WheelContact, 2> wheels;
  const int n = wheel_contacts(model, mode, t, x, wheels);
  const KinematicsJacobian D = kinematics_jacobian(model, x);
  const FrictionJacobian dF = friction_jacobian(model, mode, x, D, wheels, n);
  GearJacobian J = GearJacobian::Zero();
  strut_rows(model, x, cs.force, dF, J);
  wheel_rows(model, mode, x, wheels, n, dF, J);
  optional_rows(model, mode, x, cs, D, dF, J);
  return J;
}

}  // namespace contensou
