// Measured friction diagrams: the CSV format of theory.md section 6.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/kinematics.hpp"

namespace contensou {

// The measured channels, in the order used everywhere: Fx [N], Fy [N], Mz [N m].
inline constexpr int kChannels = 3;
inline constexpr const char* kChannelColumns[kChannels] = {"Fx_N", "Fy_N", "Mz_Nm"};

struct MeasuredPoint {
  Kinematics<double> kinematics;
  std::array<std::optional<double>, kChannels> force;  // Fx, Fy, Mz; nullopt = not measured
  std::optional<double> normal_load;                   // Fz_N
  std::optional<double> time;                          // t_s
  int line = 0;                                        // line in the file (0 if synthetic)
};

struct MeasuredData {
  std::string source;  // file name or description
  std::vector<MeasuredPoint> points;

  // Number of measured values of a channel.
  int count(int channel) const;
};

// Reads the CSV: header row, columns in any order (vx_mps, vy_mps, omega_radps required;
// Fx_N, Fy_N, Mz_Nm, Fz_N, t_s optional; other columns ignored), '#' comments, empty cell =
// not measured. Throws ParseError naming file, line and column for a malformed or non-finite
// cell, a missing required column or an empty kinematic cell, and a file without any channel.
MeasuredData read_measured_csv(const std::string& path);

// Writes the same format (with a comment header); throws std::runtime_error if it cannot.
void write_measured_csv(const std::string& path, const MeasuredData& data,
                        const std::string& comment = "");

}  // namespace contensou
