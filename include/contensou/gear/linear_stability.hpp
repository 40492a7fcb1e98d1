/// \file
/// Stability of the landing gear judged by the eigenvalues of its linearisation about a
/// quasi-steady state, and by the growth rate after a fixed standard perturbation
/// (docs/shimmy.md, "Stability criterion"). Two phases:
///   touchdown     unbraked. Sliding models: the tire slides while the wheel spins up; the wheel
///                 speed is frozen at a wheel-speed slip s (vx about s V) and the strut's motion is
///                 linearised about its equilibrium under the drag at full load (a frozen-time
///                 analysis, valid because spin-up is slow against the strut's modes only to
///                 the extent that ~3 cycles are). The von_schlippe (classical) model rolls:
///                 straight rolling, the classical shimmy analysis.
///   braked_slide  the anti-skid holds the wheel-speed slip near brake_target_slip; sliding
///                 models slide (wheel speed a state), the von_schlippe model rolls braked on its
///                 friction circle.
/// The drift (scenario.drift_speed_mps) is kept: the landing's kinematics carry it as a constant
/// lateral ground speed, so the quasi-steady state linearised here is the one the simulated
/// landings settle about (maps, eigenvalues and landings: one state).
#pragma once

#include <Eigen/Core>
#include <complex>
#include <string>
#include <vector>

#include "contensou/gear/landing_gear.hpp"

namespace contensou {

/// The phase whose quasi-steady state is linearised.
enum class StabilityPhase {
  touchdown,    ///< unbraked, at full load: sliding models with the spin frozen, else rolling
  braked_slide  ///< brake on, the anti-skid holding brake_target_slip
};
/// "touchdown" or "braked_slide".
inline const char* to_string(StabilityPhase phase) {
  return phase == StabilityPhase::touchdown ? "touchdown" : "braked_slide";
}

/// The state the linearisation is taken about, and which states it covers.
struct QuasiSteadyState {
  StabilityPhase phase = StabilityPhase::braked_slide;  ///< the phase
  GearMode mode;   ///< loaded; rolling for von_schlippe; the brake on in the braked slide
  double t = 0.0;  ///< a time after full load [s] (1 s after it): the load is N_s
  GearState x = GearState::Zero();  ///< the state found
  std::vector<int> states;          ///< the states of the linearisation (StateIndex)
  bool frozen_spin = false;         ///< touchdown of a sliding model: Omega held
  double touchdown_slip = 0.0;      ///< the frozen slip ratio (touchdown, sliding models)
  double residual = 0.0;            ///< max abs(dx/dt) over `states`, scaled by the solver's scales
  bool converged = false;           ///< residual below 1e-6
};

/// Newton's method on dx/dt = 0 over the active states (central-difference Jacobian, step
/// halving), from the wheel speed of the phase's slip. Throws InvalidArgument for a touchdown
/// slip outside (0, 1] in the touchdown of a sliding model; a failed solve is not converged.
QuasiSteadyState quasi_steady_state(const GearModel& model, StabilityPhase phase,
                                    double touchdown_slip = 0.5);

/// dx/dt of the quasi-steady problem (Omega' = 0 when the spin is frozen).
GearState quasi_steady_rhs(const GearModel& model, const QuasiSteadyState& q, const GearState& x);

/// Central-difference Jacobian of quasi_steady_rhs over q.states, about q.x (steps of 1e-6 of
/// each state's scale); rows and columns in q.states' order.
Eigen::MatrixXd linearise(const GearModel& model, const QuasiSteadyState& q);

/// Work per cycle done on the gear by each term of the linearised dynamics along the dominant
/// oscillatory mode [J per cycle], at the amplitude StabilityReport::energy states. Positive work
/// feeds the oscillation. For a mode q(t) = Re(q^ e^{i w t}) the work of a force F on a rate v over
/// one period 2 pi / w is (pi / w) Re(F^ conj(v^)) (growth within the cycle neglected).
struct EnergyPerCycle {
  double spin_torque = 0.0;          ///< Mz on psi'
  double trail_lateral_force = 0.0;  ///< -e Fy on psi'
  double offset_drag = 0.0;          ///< -l Fx on psi'
  double torsional_damping = 0.0;    ///< -c_psi psi' on psi'
  double lateral_friction = 0.0;     ///< (Fx sin psi + Fy cos psi) on y'
  double lateral_damping = 0.0;      ///< -c_y y' on y'
  /// Carcass compliance only (GearStructure::carcass_*): the drag's lever grows by e_y,
  /// -(e_y Fx)' = -(e_y0 dFx + Fx0 de_y) on psi'.
  double carcass_lever = 0.0;
  /// Of the friction terms above, the part due to the fall of friction with slip speed: their sum
  /// less the same with f held at its operating value (df/dw = 0). Not a term of total().
  double fall_of_friction = 0.0;
  /// The sum of the terms (without fall_of_friction) [J per cycle].
  double total() const {
    return spin_torque + trail_lateral_force + offset_drag + torsional_damping + lateral_friction +
           lateral_damping + carcass_lever;
  }
};

/// The eigenvalues of one phase's linearisation, the modes that matter, the contact's slopes and
/// the standard perturbation's response.
struct StabilityReport {
  QuasiSteadyState state;                         ///< the state linearised about
  std::vector<std::complex<double>> eigenvalues;  ///< [1/s], sorted by decreasing real part
  double max_real_part = 0.0;                     ///< over all eigenvalues [1/s]
  /// Largest real part of an oscillatory eigenvalue (Im above 0.5 Hz) [1/s]; max_real_part
  /// without one.
  double growth_rate_per_s = 0.0;
  double frequency_hz = 0.0;  ///< of that mode [Hz]; 0 without one
  /// abs(psi) / (abs(psi) + abs(y) / 0.1 m) in that mode's eigenvector.
  double torsion_share = 0.0;
  /// What that mode moves most, comparing abs(psi) x 1 m, abs(y), abs(x) and the tire's
  /// longitudinal deflection abs(u) in its eigenvector: "torsion", "lateral" (both shimmy),
  /// "fore-aft" (gear walk) or "longitudinal" (the wheel spinning against the tire's longitudinal
  /// deflection); empty without an oscillatory mode.
  std::string mode_kind;
  /// The torsional mode: the oscillatory eigenvalue with the largest share of torsion against
  /// lateral and longitudinal tire deflection, abs(psi) / (abs(psi) + (abs(y) + abs(u)) / 0.1 m)
  /// (what the standard perturbation, a kick of psi', measures); its real part [1/s], 0 without
  /// an oscillatory mode.
  double torsion_growth_rate_per_s = 0.0;
  double torsion_frequency_hz = 0.0;  ///< the torsional mode's frequency [Hz]
  /// Slope of the friction torque against psi' at the state (-dMz/dpsi') [N m s/rad]: what the
  /// contact adds to the torsional damping (decoupled model: about M0 R / eps).
  double spin_torque_damping_nms_per_rad = 0.0;
  /// Slope of the drag against the sliding speed the law reads, -dFx/dvx [N s/m], summed over
  /// the wheels: (dFx/dOmega) / r where the law reads the kinematic vx, -(dFx/du) sigma_x / V
  /// with longitudinal relaxation on (the law reads V u / sigma_x); negative on the falling part
  /// of f(w) (docs/shimmy.md, "Where the energy comes from").
  double drag_slope_ns_per_m = 0.0;
  double friction = 0.0;  ///< f at the state
  /// Of the dominant oscillatory mode at an amplitude of 1 mrad of torsion or 1 mm of lateral or
  /// fore-aft deflection, whichever the mode moves most (abs(psi) x 1 m against abs(y), abs(x))
  /// [J]; zeros without an oscillatory mode.
  EnergyPerCycle energy;
  /// The standard perturbation: psi' += perturbation_rate_radps at the quasi-steady state,
  /// integrated with CVODE for perturbation_window_s in the same mode; the growth rate [1/s]
  /// fitted to the torsion's rate peaks (analyse_oscillation), NaN if it does not oscillate, was
  /// not run or the state did not converge.
  double perturbation_growth_rate_per_s = 0.0;
  double perturbation_frequency_hz = 0.0;  ///< the perturbation's frequency [Hz], NaN likewise
  /// Every eigenvalue's real part negative.
  bool stable() const { return max_real_part < 0.0; }
};

/// What assess_stability() does besides the eigenvalues.
struct StabilityOptions {
  double touchdown_slip = 0.5;           ///< the frozen slip ratio (touchdown, sliding models)
  bool simulate_perturbation = true;     ///< run the standard perturbation
  double perturbation_rate_radps = 0.1;  ///< psi' kick [rad/s]
  double perturbation_window_s = 0.5;    ///< how long the perturbation is integrated [s]
};

/// The report of one phase: quasi-steady state, eigenvalues, modes, energy per cycle and (if
/// asked and converged) the standard perturbation. Throws InvalidArgument as quasi_steady_state
/// does, std::runtime_error if CVODE fails on the perturbation run.
StabilityReport assess_stability(const GearModel& model, StabilityPhase phase,
                                 const StabilityOptions& options = {});

/// The touchdown phase over the spin-up: the worst report over frozen slip ratios
/// 0.9, 0.7, 0.5, 0.3, 0.1 (sliding models; the largest growth rate among the converged, with
/// the perturbation run at that slip), or the straight-rolling report (von_schlippe).
StabilityReport assess_touchdown(const GearModel& model, const StabilityOptions& options = {});

/// The largest real part of an oscillatory eigenvalue of the touchdown (worst frozen slip) or
/// braked slide linearisation [1/s], without the perturbation run: the quantity the maps show;
/// NaN if the quasi-steady state did not converge.
double linear_growth_rate(const GearModel& model, StabilityPhase phase);

/// The torsional damping at which the classical (von_schlippe, unbraked) model loses stability at
/// the model's forward speed: bisection on the sign of the largest real part [N m s/rad];
/// 0 if stable without damping. Throws std::runtime_error if no damping it tries (doubling up to
/// about 7e7 N m s/rad) is stable.
double classical_critical_damping(const GearModel& model);

}  // namespace contensou
