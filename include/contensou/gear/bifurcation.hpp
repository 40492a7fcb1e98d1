// Bifurcation diagrams of the braked slide (docs/shimmy.md, "Bifurcation diagrams"): the
// torsional limit cycle's amplitude and torque-link load against one parameter, by continuation.
// Each point integrates the gear in the braked slide's fixed mode (loaded, brake on, the
// quasi-steady state's contact mode; no events) from the previous point's end state, carried as
// its deviation from the new quasi-steady state, until the amplitude has settled
// (cycle_trend.hpp) or the longest run is reached. The sweep runs up from a small kick (it finds
// the onset) and down from a large swing (it stays on a subcritical branch below the linear
// boundary: hysteresis). Each point also carries the linearisation's growth rate and frequency.
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

struct SweepOptions {
  double settle_s = 1.0;                  // each point runs at least this long
  double longest_s = 8.0;                 // doubled while not settled, up to this
  double seed_rate_radps = 0.01;          // psi' kick where the oscillation has died out (up)
  double start_amplitude_rad = 0.06;      // the down sweep's first point starts from this twist
  double relative_tolerance = 1e-7;       // CVODE (Adams-Moulton, the structured Jacobian)
  double output_interval_s = 5e-4;        // samples of psi, psi'
  double amplitude_threshold_rad = 1e-3;  // a limit cycle is above it
  StopRequest stop{};
};

struct SweepPoint {
  double value = 0.0;  // the parameter
  CycleState state = CycleState::not_measured;
  double amplitude_rad = 0.0;   // half the psi swing over the last period
  double torque_link_nm = 0.0;  // half the swing of k_psi psi + c_psi psi' over the last period
  double trend_per_s = 0.0;     // of ln(amplitude) over the last kTrendPeriods periods
  double frequency_hz = 0.0;    // of the simulated oscillation (zero crossings); 0 if none
  double run_s = 0.0;           // how long this point ran
  // Up sweep, where it settles on a cycle: the time from a kick of seed_rate_radps at the
  // quasi-steady state until the half swing first reaches half the settled amplitude (the time
  // to onset; its own run where the sweep carried the cycle in); NaN otherwise.
  double onset_s = 0.0;
  double eigen_growth_per_s = 0.0;  // the linearisation's dominant oscillatory mode
  double eigen_frequency_hz = 0.0;
  bool valid = false;  // the quasi-steady state was found and the run finished
  std::string error;
};

struct BifurcationSweep {
  ContactModel contact = ContactModel::coupled;
  MapAxis axis;  // parameter, from, to, points
  // Every parameter value where the eigenvalue growth changes sign along the axis (linear
  // interpolation between points), in increasing order; linear_boundary is the first (NaN if
  // there is none).
  std::vector<double> linear_boundaries;
  double linear_boundary = 0.0;
  std::vector<SweepPoint> up, down;  // both in increasing parameter order
};

// One parameter, both directions, for one model. Throws InvalidArgument for a bad axis
// (check_map_axis) or options; a point that fails is marked invalid with its error, and the
// next point starts again from the quasi-steady state.
BifurcationSweep bifurcation_sweep(const GearModel& base, const MapAxis& axis,
                                   const SweepOptions& options = {});

// Several sweeps (every model with every axis), both directions of each on its own thread
// (usable_threads); `progress(done, total)` counts directions done, from the calling thread.
std::vector<BifurcationSweep> bifurcation_sweeps(const std::vector<GearModel>& models,
                                                 const std::vector<MapAxis>& axes,
                                                 const SweepOptions& options, unsigned threads,
                                                 const std::function<void(int, int)>& progress);

}  // namespace contensou
