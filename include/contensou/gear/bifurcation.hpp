/// \file
/// Bifurcation diagrams of the braked slide (docs/shimmy.md, "Bifurcation diagrams"): the
/// torsional limit cycle's amplitude and torque-link load against one parameter, by continuation.
/// Each point integrates the gear in the braked slide's fixed mode (loaded, brake on, the
/// quasi-steady state's contact mode; no events) from the previous point's end state, carried as
/// its deviation from the new quasi-steady state, until the amplitude has settled
/// (cycle_trend.hpp) or the longest run is reached. The sweep runs up from a small kick (it finds
/// the onset) and down from a large swing (it stays on a subcritical branch below the linear
/// boundary: hysteresis). Each point also carries the linearisation's growth rate and frequency.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/cycle_trend.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "contensou/gear/stability_map.hpp"

namespace contensou {

/// How each point of a sweep runs. Throws InvalidArgument (from the sweep) unless the times,
/// tolerance, interval and threshold are positive, longest_s is at least settle_s, the kick and
/// the twist are finite and longest_s / output_interval_s is at most 1e6.
struct SweepOptions {
  double settle_s = 1.0;   ///< each point runs at least this long [s]
  double longest_s = 8.0;  ///< doubled while not settled, up to this [s]
  /// psi' kick where the oscillation has died out (up) [rad/s].
  double seed_rate_radps = 0.01;
  /// The down sweep's first point starts from this twist [rad].
  double start_amplitude_rad = 0.06;
  double relative_tolerance = 1e-7;       ///< CVODE (Adams-Moulton, the structured Jacobian)
  double output_interval_s = 5e-4;        ///< samples of psi, psi' [s]
  double amplitude_threshold_rad = 1e-3;  ///< a limit cycle is above it [rad]
  /// Polled before every sample: the sweep throws Interrupted once it returns true (error.hpp).
  StopRequest stop{};
};

/// One parameter value of one direction.
struct SweepPoint {
  double value = 0.0;                           ///< the parameter, in its key's unit
  CycleState state = CycleState::not_measured;  ///< how the run ended (cycle_trend)
  double amplitude_rad = 0.0;                   ///< half the psi swing over the last period [rad]
  /// Half the swing of k_psi psi + c_psi psi' over the last period [N m].
  double torque_link_nm = 0.0;
  double trend_per_s = 0.0;   ///< of ln(amplitude) over the last kTrendPeriods periods [1/s]
  double frequency_hz = 0.0;  ///< of the simulated oscillation (zero crossings) [Hz]; 0 if none
  double run_s = 0.0;         ///< how long this point ran [s]
  /// Up sweep, where the motion settles on a cycle or still grows: the time [s] from a kick of
  /// seed_rate_radps at the quasi-steady state until a period's half swing first reaches
  /// amplitude_threshold_rad (the time to onset; its own run where the sweep carried the motion
  /// in); NaN where it does not within the run, and on decaying or settled-small points.
  double onset_s = 0.0;
  double eigen_growth_per_s = 0.0;  ///< the linearisation's dominant oscillatory mode [1/s]
  double eigen_frequency_hz = 0.0;  ///< its frequency [Hz]
  bool valid = false;               ///< the quasi-steady state was found and the run finished
  std::string error;                ///< why the point is not valid; empty when it is
};

/// Both directions of one parameter for one model.
struct BifurcationSweep {
  ContactModel contact = ContactModel::coupled;  ///< the model swept
  MapAxis axis;                                  ///< parameter, from, to, points
  /// Every parameter value where the up sweep's eigenvalue growth changes sign between two
  /// points without error (linear interpolation), in the axis' order (increasing when
  /// from < to); linear_boundary is the first (NaN if there is none).
  std::vector<double> linear_boundaries;
  double linear_boundary = 0.0;  ///< the first of linear_boundaries, NaN if none
  /// The up sweep, run from `from` to `to`; stored in the axis' order.
  std::vector<SweepPoint> up, down;  ///< the down sweep, run from `to` to `from`; the same order
};

/// One parameter, both directions, for one model. Throws InvalidArgument for a bad axis
/// (check_map_axis) or options, Interrupted when options.stop asks; a point that fails is marked
/// invalid with its error, and the next point starts again from the quasi-steady state.
BifurcationSweep bifurcation_sweep(const GearModel& base, const MapAxis& axis,
                                   const SweepOptions& options = {});

/// Several sweeps (every model with every axis, model by model), both directions of each on its
/// own thread (`threads`, 0: all cores); `progress(done, total)` counts directions done, from the
/// calling thread. Throws as bifurcation_sweep does.
std::vector<BifurcationSweep> bifurcation_sweeps(const std::vector<GearModel>& models,
                                                 const std::vector<MapAxis>& axes,
                                                 const SweepOptions& options, unsigned threads,
                                                 const std::function<void(int, int)>& progress);

}  // namespace contensou
