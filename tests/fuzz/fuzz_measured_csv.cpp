// Fuzzes read_measured_csv: a ParseError is the only expected failure; a file that is read
// must give finite kinematics and forces, positive normal loads and increasing line numbers.
#include <cmath>
#include <optional>

#include "contensou/friction/error.hpp"
#include "contensou/identification/measured_data.hpp"
#include "fuzz_input.hpp"

using namespace contensou;

namespace {

bool finite_or_empty(const std::optional<double>& v) {
  return !v || std::isfinite(*v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = fuzz::write_input(data, size, "csv");
  MeasuredData d;
  try {
    d = read_measured_csv(path);
  } catch (const ParseError&) {
    return 0;
  }
  int previous_line = 0;
  for (const MeasuredPoint& p : d.points) {
    const std::string at = "point at line " + std::to_string(p.line);
    fuzz::require(p.line > previous_line, at + ": line numbers not increasing");
    previous_line = p.line;
    fuzz::require(std::isfinite(p.kinematics.vx) && std::isfinite(p.kinematics.vy) &&
                      std::isfinite(p.kinematics.omega),
                  at + ": non-finite kinematics");
    for (const auto& f : p.force) fuzz::require(finite_or_empty(f), at + ": non-finite force");
    fuzz::require(!p.normal_load || *p.normal_load > 0.0, at + ": Fz_N not positive");
    fuzz::require(finite_or_empty(p.normal_load) && finite_or_empty(p.time),
                  at + ": non-finite Fz_N or t_s");
  }
  for (int c = 0; c < kChannels; ++c)
    fuzz::require(d.count(c) >= 0 && d.count(c) <= static_cast<int>(d.points.size()),
                  "channel count out of range");
  return 0;
}
