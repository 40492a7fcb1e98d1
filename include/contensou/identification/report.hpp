/// \file
/// The identification report as JSON: the schema written by contensou-identify --json, shared
/// by the app and the Python package (contensou.identify(...).to_json()). It reads the results
/// of the fit and the loop and the description of the input (ProfileChoice: profile_choice.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/pressure_profile.hpp"
#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/data_checks.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/held_out.hpp"
#include "contensou/identification/key_style.hpp"
#include "contensou/identification/outliers.hpp"
#include "contensou/identification/profile_choice.hpp"

namespace contensou {

/// A recorded column of the data (measured_data.hpp), as the report lists it.
struct RecordedSummary {
  RecordedVariable variable;  ///< the column
  /// Smallest value over the rows that have a value, in variable.si_unit.
  double min = 0.0, max = 0.0;  ///< largest value over those rows, in variable.si_unit
  int values = 0;               ///< the number of rows with a value
  /// "'T [degC]' (column 8): 20.1 to 45.3 degC (293.25 to 318.45 K), 120 values" (the range in
  /// the file's unit, then in SI when a known unit was converted).
  std::string describe() const;
};

/// What the report says about its input (the "input" object).
struct ReportInput {
  std::string file;                           ///< the file read, or the data's source
  std::vector<std::string> sources;           ///< the files, when several were fitted together
  int points = 0;                             ///< the data's rows
  int values = 0;                             ///< measured values, over all channels
  double radius_m = 0.0;                      ///< patch radius R [m]
  std::optional<double> normal_load_n;        ///< normal load N [N], if known
  std::string normal_load_source;             ///< where N came from ("" if given directly)
  std::vector<std::string> column_notes;      ///< columns read under other names or units
  std::vector<RecordedSummary> recorded;      ///< the file's columns the law does not read
  std::vector<std::string> columns_not_read;  ///< and those not read at all, with the reason
  std::vector<std::string> missing_values;    ///< missing cells a column, with their spellings
  std::vector<Outlier> outliers;              ///< gross errors left out of the fit
  std::vector<Outlier> put_back;  ///< first taken for gross errors, fitted by the final model
  std::string profile;            ///< how the pressure profile was given ("" if none)
  std::optional<double> profile_rms_residual_pa;  ///< a smoothing fit's rms residual [Pa]
  std::optional<double> profile_max_residual_pa;  ///< a smoothing fit's largest residual [Pa]
  /// What the rows can determine, checked before any fit (data_checks.hpp; describe_run).
  DataChecks checks;
  /// The identification judged on rows its fits never saw (held out, or other files).
  std::vector<HeldOutResult> held_out;
};

/// The report of a fit alone: input, base, steps (empty), accepted_effects, final (= base),
/// error_before, error_after. `indent` as nlohmann::json::dump (2 in the app's files).
std::string fit_report_json(const ReportInput& input, const FitReport& base, int indent = 2);

/// The report of a closed loop: the above with the steps, accepted effects, ambiguities, final
/// model and errors before and after, the noise model and the summary in words.
std::string loop_report_json(const ReportInput& input, const ClosedLoopReport& loop,
                             int indent = 2);

/// The report's description of a run: the file (or source), the data's point and value counts,
/// the files when several, the columns' notes, the recorded columns' ranges, the radius, the
/// load and the profile as chosen. normal_load_source and outliers are left empty.
ReportInput describe_run(const std::string& file, const MeasuredData& data, double radius_m,
                         std::optional<double> normal_load_n, const ProfileChoice& profile);

}  // namespace contensou
