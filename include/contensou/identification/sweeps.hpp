/// \file
/// The sweeps of a measured diagram: the rows that share a file, a normal load, a spin speed and
/// sense and a sliding direction, along which only the sliding-spin ratio psi = v / (|omega| R)
/// changes (theory.md §2). The pictures draw one curve a sweep; fit.csv names each row's sweep.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// One sweep: its rows and what they share.
struct Sweep {
  int file = 0;                         ///< MeasuredData::sources index
  std::optional<double> load_n;         ///< the sweep's mean normal load [N], if the rows carry one
  std::optional<double> direction_rad;  ///< atan2(vy, vx), to 1 degree; nullopt: pure spin (v = 0)
  double spin_speed_mps = 0.0;          ///< u = |omega| R, the mean over the sweep [m/s]
  int spin_sign = 1;                    ///< sign of omega (+1 for omega = 0, pure sliding)
  std::string label;                    ///< what tells it from the others ("Fz 4.54 kN, 90 deg")
  std::vector<std::size_t> points;      ///< indices into MeasuredData::points, in increasing psi
};

/// Groups every row into exactly one sweep. Loads and spin speeds within 3 % of each other are one
/// level (sorted values, a new level at a gap above 3 %); the sign of omega splits sweeps too;
/// directions are binned to the degree. Labels name only what varies between sweeps ("all rows"
/// when nothing does). Sweeps are ordered by file, load, spin speed, spin sign, direction.
/// Throws InvalidArgument for a radius [m] that is not positive and finite.
std::vector<Sweep> sweeps_of(const MeasuredData& data, double radius_m);

/// A sample of about `target` rows (never fewer) that keeps the data's design: about every
/// (rows / target)-th row of each sweep in psi order (its first and last always), and the rows at
/// the smallest and largest load, time, value of each recorded column and the first and last row in
/// file order, so that every variable keeps its range. One entry a row, 1 where sampled; every row
/// when the data have at most `target`, or `target` is 0. Throws as sweeps_of.
std::vector<char> stratified_sample(const MeasuredData& data, double radius_m, std::size_t target);

}  // namespace contensou
