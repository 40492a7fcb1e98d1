// The law FMU's resource file (resources/law.txt): the friction law an FMU evaluates, written by
// the exporter and read by the FMU binary at instantiation. Text, one record a line:
//   contensou-fmu-law 1                      (first line: the format and its version)
//   <name> <count> <v1> ... <vcount>         (numbers in C99 hexadecimal floating point, %a,
//                                            so that the tables are read back bit for bit)
//   text <name> <rest of the line>           (strings)
// '#' starts a comment line. The exact law's tables (ExactLaw: the six functions of t and, for
// a slip-speed law, the falling part's table) or the fractional law's coefficients are stored
// as built at export; reading checks every size, order and value and names the line of the
// first bad one (ParseError), so that a damaged or foreign file is refused, never evaluated.
#pragma once

#include <optional>
#include <string>

#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/fractional_law.hpp"

namespace contensou::fmu {

inline constexpr const char* kLawResourceName = "law.txt";

struct LawResource {
  std::string guid;            // the modelDescription's guid (instantiation checks it)
  std::string description;     // the patch in words
  double normal_load_n = 0.0;  // N of the patch at export (the start value of the input N)
  // The patch's data shown as constants of the FMU.
  double radius_m = 0.0, friction = 0.0, kappa = 1.0, kx = 0.0, ky = 0.0;
  double error_bound = 0.0;  // the exact law's certified bound (relative to f N, f N R); 0 else
  // One of the two: the exact law's tables, or the fractional law at the export load.
  std::optional<ExactLaw> exact;
  std::optional<FractionalLaw<double>> fractional;
};

// The file's text.
std::string write_law_resource(const LawResource& resource);

// Parses and checks a file's text; `source` names it in errors. Throws ParseError
// ("source:line: message") for anything malformed, inconsistent or out of range.
LawResource read_law_resource(const std::string& text, const std::string& source);

}  // namespace contensou::fmu
