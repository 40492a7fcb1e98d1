/// \file
/// How far the fractional law is from the exact integrals (theory.md section 5).
#pragma once

#include <string>
#include <vector>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/fractional_law.hpp"

namespace contensou {

/// Error of one channel of one law over the ratios, relative to F0 (forces) or M0 (torque).
struct ChannelError {
  std::string channel;   ///< "F_par", "F_lat", "Mz"
  double max_error = 0;  ///< max |law - exact| / scale
  double rms_error = 0;  ///< root mean square of |law - exact| / scale
  double worst_psi = 0;  ///< psi = v/u where the maximum occurs
};

/// One coefficient set of the fractional law and its errors.
struct LawError {
  std::string name;                    ///< "asymptote-matched" or "least-squares"
  FractionalLaw<double> law;           ///< its coefficients
  std::vector<ChannelError> channels;  ///< one per channel
};

/// The fractional laws against the exact integrals (model_error_report).
struct ModelErrorReport {
  double psi_min = 1e-3;       ///< smallest psi = v/u compared
  double psi_max = 1e3;        ///< largest psi compared
  int points = 0;              ///< log-spaced psi values
  std::vector<LawError> laws;  ///< the coefficient sets
};

/// Compares both coefficient sets with the exact integrals, sliding along x, at `points`
/// log-spaced psi = v/u in [psi_min, psi_max]. F_lat is reported when the patch has kx != 0.
/// Throws InvalidArgument for an invalid patch, psi_min <= 0, psi_max <= psi_min or points < 2.
ModelErrorReport model_error_report(const ContactPatch& patch, double psi_min = 1e-3,
                                    double psi_max = 1e3, int points = 61);

/// A plain-text table of the report.
std::string format_report(const ModelErrorReport& report);

}  // namespace contensou
