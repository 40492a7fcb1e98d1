/// \file
/// Functional Mock-up Units (FMI 2.0; the law also FMI 3.0) of contensou, for Modelica, Simulink,
/// FMPy and any other FMI importer (docs/fmu.md):
///   - the friction law of a contact patch: inputs vx, vy, omega, N; outputs Fx, Fy, Mz; Model
///     Exchange and Co-Simulation in one archive, directional derivatives from the law's
///     Jacobian, the exact law's tables built here and shipped in resources/law.txt;
///   - the one-wheel landing gear of the shimmy demo (Co-Simulation, CVODE inside): inputs the
///     forward speed and a brake-torque command, parameters the demo's configuration keys.
/// The FMU binaries are built with the project and embedded in the exporter, which writes the
/// archive (modelDescription.xml, binaries/linux64/, resources/) atomically.
#pragma once

#include <cstddef>
#include <string>

#include "contensou/friction/contact_patch.hpp"

namespace contensou::fmu {

/// The law an exported FMU evaluates.
enum class FmuLaw {
  exact,      ///< the exact law (tabulated exact integrals, theory.md), the default
  fractional  ///< the fractional (Pade-type) law of the patch
};

/// Options of export_law_fmu.
struct LawFmuOptions {
  FmuLaw law = FmuLaw::exact;  ///< the law the FMU evaluates
  int fmi_version = 2;         ///< 2 (FMI 2.0) or 3 (FMI 3.0: binaries/x86_64-linux)
  double tolerance = 1e-8;     ///< the exact law's, relative to f N and f N R (ExactLawOptions)
  unsigned threads = 0;        ///< of the exact law's build (0: one a core)
  std::string model_name = "contensou_law";  ///< modelName in modelDescription.xml
  std::string profile_text;  ///< how the profile was given, for the description ("" : describe())
};

/// What an export wrote.
struct FmuExport {
  std::string path;             ///< the archive written
  std::string guid;             ///< the FMU's guid (FMI 2.0) or instantiation token (FMI 3.0)
  std::size_t bytes = 0;        ///< of the archive
  double error_bound = 0.0;     ///< the exact law's certified bound (relative); 0 for fractional
  std::size_t table_bytes = 0;  ///< of resources/law.txt
  double build_s = 0.0;         ///< building the law
};

/// Writes the law FMU of `patch` to `path` (.fmu). Throws InvalidArgument for a bad patch or
/// option (a slip-speed law with the fractional law), std::runtime_error if the file cannot be
/// written (nothing is left at `path` then).
FmuExport export_law_fmu(const ContactPatch& patch, const std::string& path,
                         const LawFmuOptions& options = {});

/// Writes the gear FMU to `path` (FMI 2.0 or 3.0, Co-Simulation).
FmuExport export_gear_fmu(const std::string& path, int fmi_version = 2);

}  // namespace contensou::fmu
