/// \file
/// An identification judged on rows its fits never saw (held out of the file, or other files):
/// the base law's and the final model's error and both-ways predictions there (prediction.hpp),
/// and each step of the closed loop scored by the held-out error of the model it extends and of
/// the extended one, beside its in-sample tests.
#pragma once

#include <string>
#include <vector>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/prediction.hpp"

namespace contensou {

/// A loop step on the held-out rows.
struct HeldOutStep {
  std::string effect;         ///< the step's effect (LoopStep::effect)
  std::string detail;         ///< and its detail (LoopStep::detail)
  bool accepted = false;      ///< accepted and not removed
  double error_before = 0.0;  ///< prediction_error of the model it extends
  double error_after = 0.0;   ///< prediction_error of the extended model
};

/// The identification on one set of held-out rows.
struct HeldOutResult {
  std::string name;                ///< "held out of data.csv (20 %, sweeps)", or the file's name
  int rows = 0;                    ///< the rows judged
  double base_error = 0.0;         ///< prediction_error of the base law
  double final_error = 0.0;        ///< prediction_error of the final model
  PredictionScores base_scores;    ///< both-ways scores of the base law
  PredictionScores final_scores;   ///< both-ways scores of the final model
  std::vector<HeldOutStep> steps;  ///< each fitted loop step (none without the loop)
};

/// Judges the base law `base` and the loop `loop` (may be null: the law alone) on `rows`, named
/// `name` in the report. Throws what predict_rows throws (a model whose friction follows a
/// recorded column the rows lack: InvalidArgument naming it).
HeldOutResult judge_on_rows(const FitReport& base, const ClosedLoopReport* loop,
                            const MeasuredData& rows, const std::string& name);

/// The result in words, a few lines ("held out of ...: 100 rows; error 0.21 (base law) -> 0.19
/// (final model); ...; per step ...").
std::string held_out_text(const HeldOutResult& result);

}  // namespace contensou
