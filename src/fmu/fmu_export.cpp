#include "contensou/fmu/fmu_export.hpp"

#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/file_output.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/printable_text.hpp"
#include "contensou/version.hpp"
#include "embedded_binaries.hpp"
#include "fmu_model.hpp"
#include "law_resource.hpp"
#include "zip_writer.hpp"
#ifdef CONTENSOU_FMU_HAVE_GEAR
#include "gear_variables.hpp"
#endif

namespace contensou::fmu {

namespace {

// The text of an XML attribute: &, <, >, " and newlines escaped; a character XML 1.0 cannot
// carry at all (a control character, a byte that is not UTF-8) refused (the options are checked
// before, so this names only a text the exporter made itself).
std::string xml(const std::string& s) {
  require_printable("XML text", s);
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\n':
        out += "&#10;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The SI base-unit exponents of the units the FMUs use (FMI 2.0.4, section 2.2.2); a unit not
// listed is declared by name only.
std::string unit_definitions(const std::set<std::string>& units) {
  static const std::map<std::string, std::string> base{
      {"m", R"(m="1")"},
      {"m/s", R"(m="1" s="-1")"},
      {"rad", R"(rad="1")"},
      {"rad/s", R"(s="-1" rad="1")"},
      {"s", R"(s="1")"},
      {"1/s", R"(s="-1")"},
      {"N", R"(kg="1" m="1" s="-2")"},
      {"N m", R"(kg="1" m="2" s="-2")"},
      {"N/m", R"(kg="1" s="-2")"},
      {"N s/m", R"(kg="1" s="-1")"},
      {"N m/rad", R"(kg="1" m="2" s="-2" rad="-1")"},
      {"N m s/rad", R"(kg="1" m="2" s="-1" rad="-1")"},
      {"kg", R"(kg="1")"},
      {"kg m2", R"(kg="1" m="2")"},
      {"Pa", R"(kg="1" m="-1" s="-2")"},
      {"1/rad", R"(rad="-1")"},
      {"m/rad", R"(m="1" rad="-1")"},
      {"N m2/rad", R"(kg="1" m="3" s="-2" rad="-1")"},
      {"1", ""}};
  std::string out = "  <UnitDefinitions>\n";
  for (const std::string& u : units) {
    const auto it = base.find(u);
    out += "    <Unit name=\"" + xml(u) + "\">";
    if (it != base.end() && !it->second.empty()) out += "<BaseUnit " + it->second + "/>";
    out += "</Unit>\n";
  }
  return out + "  </UnitDefinitions>\n";
}

// FMI 2.0: guid and the number of event indicators; FMI 3.0: instantiationToken.
std::string header(const std::string& name, const std::string& guid, const std::string& description,
                   int fmi) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<fmiModelDescription fmiVersion=\"" +
         std::string(fmi == 3 ? "3.0" : "2.0") + "\" modelName=\"" + xml(name) + "\" " +
         (fmi == 3 ? "instantiationToken" : "guid") + "=\"" + guid + "\"\n  description=\"" +
         xml(description) + "\"\n  generationTool=\"contensou-fmu " + kVersion + "\" version=\"" +
         kVersion + "\" license=\"Apache-2.0\" variableNamingConvention=\"structured\"" +
         (fmi == 3 ? "" : " numberOfEventIndicators=\"0\"") + ">\n";
}

// The binary's folder in the archive (FMI 2.0.4 section 2.3; FMI 3.0 section 2.5.1).
std::string binary_path(int fmi, const char* id) {
  return std::string(fmi == 3 ? "binaries/x86_64-linux/" : "binaries/linux64/") + id + ".so";
}

void check_fmi_version(int fmi) {
  if (fmi != 2 && fmi != 3)
    throw InvalidArgument("fmi_version", std::to_string(fmi), "must be 2 (FMI 2.0) or 3 (FMI 3.0)");
}

const char* kLogCategories =
    "  <LogCategories>\n"
    "    <Category name=\"logStatusError\" description=\"calls refused with an error\"/>\n"
    "  </LogCategories>\n";

// ---- the law ----

std::string friction_text(const ContactPatch& p) {
  if (p.slip_speed_friction) {
    const SlipSpeedFriction<double>& s = *p.slip_speed_friction;
    return "f(w) = " + format_value(s.kinetic_coefficient) + " + (" +
           format_value(s.static_coefficient) + " - " + format_value(s.kinetic_coefficient) +
           ") exp(-(w / " + format_value(s.reference_speed) + " m/s)^" + format_value(s.exponent) +
           ")";
  }
  return "f = " + format_value(p.friction);
}

std::string patch_description(const ContactPatch& p, const LawFmuOptions& o, double N,
                              double bound) {
  std::string law = o.law == FmuLaw::exact
                        ? "the exact law (tables of the exact integrals, within " +
                              format_value(bound) + " of f N and f N R)"
                        : "the fractional (Pade-type) law";
  return "contensou friction law of a contact patch: R = " + format_value(p.radius_m) +
         " m, pressure profile " + (o.profile_text.empty() ? describe(p.profile) : o.profile_text) +
         ", p* = " + format_value(p.reference_pressure_pa) + " Pa (N = " + format_value(N) +
         " N at export), " + friction_text(p) + ", kappa = " + format_value(p.kappa) +
         ", shift kx = " + format_value(p.profile.kx) + ", ky = " + format_value(p.profile.ky) +
         "; " + law +
         ". Inputs vx, vy [m/s], omega [rad/s], N [N]; outputs Fx, Fy [N], Mz [N m] "
         "on the tire (theory.md section 1).";
}

struct LawVar {
  const char* name;
  const char* causality;
  const char* unit;
  const char* description;
};

// One scalar variable: FMI 2.0's <ScalarVariable><Real .../></ScalarVariable> or FMI 3.0's
// <Float64 .../> (and <Boolean>, <String>).
struct Scalar {
  std::string name, causality, variability, initial, description, type = "Real", unit, start;
  std::size_t reference = 0;
};

std::string scalar_variable(const Scalar& v, int fmi) {
  std::string attributes = " name=\"" + xml(v.name) + "\" valueReference=\"" +
                           std::to_string(v.reference) + "\" causality=\"" + v.causality +
                           "\" variability=\"" + v.variability + "\"" +
                           (v.initial.empty() ? "" : " initial=\"" + v.initial + "\"");
  const std::string typed = (v.unit.empty() ? "" : " unit=\"" + xml(v.unit) + "\"") +
                            (v.causality == "output" ? "" : " start=\"" + xml(v.start) + "\"");
  if (fmi == 3) {
    const std::string element = v.type == "Real" ? "Float64" : v.type;
    if (element == "String")  // FMI 3.0: the start value is a child element
      return "    <String" + attributes + " description=\"" + xml(v.description) +
             "\">\n      <Start value=\"" + xml(v.start) + "\"/>\n    </String>\n";
    return "    <" + element + attributes + typed + "\n      description=\"" + xml(v.description) +
           "\"/>\n";
  }
  return "    <ScalarVariable" + attributes + "\n      description=\"" + xml(v.description) +
         "\">\n      <" + v.type + typed + "/>\n    </ScalarVariable>\n";
}

// ModelStructure: FMI 2.0 names the outputs by their 1-based index in ModelVariables, FMI 3.0 by
// value reference (here the index less one). `dependencies` as indices (FMI 2.0) or "".
std::string model_structure(const std::vector<std::size_t>& outputs, const std::string& deps,
                            int count, int fmi) {
  std::string kinds;
  for (int k = 0; k < count; ++k) kinds += k ? " dependent" : "dependent";
  auto unknown = [&](const char* element, std::size_t index) {
    std::string d;
    if (!deps.empty()) {
      d = " dependencies=\"";
      std::size_t from = 0;
      for (std::size_t at; (at = deps.find(' ', from)) != std::string::npos || from < deps.size();
           from = at == std::string::npos ? deps.size() : at + 1) {
        const int i = std::stoi(deps.substr(from, at - from));
        d += (from ? " " : "") + std::to_string(fmi == 3 ? i - 1 : i);
        if (at == std::string::npos) break;
      }
      d += "\" dependenciesKind=\"" + kinds + "\"";
    }
    return fmi == 3 ? "    <" + std::string(element) + " valueReference=\"" +
                          std::to_string(index - 1) + "\"" + d + "/>\n"
                    : "      <Unknown index=\"" + std::to_string(index) + "\"" + d + "/>\n";
  };
  std::string out = "  <ModelStructure>\n";
  if (fmi == 3) {
    for (std::size_t i : outputs) out += unknown("Output", i);
    for (std::size_t i : outputs) out += unknown("InitialUnknown", i);
  } else {
    for (const char* part : {"Outputs", "InitialUnknowns"}) {
      out += std::string("    <") + part + ">\n";
      for (std::size_t i : outputs) out += unknown("Unknown", i);
      out += std::string("    </") + part + ">\n";
    }
  }
  return out + "  </ModelStructure>\n";
}

// FMI 3.0's independent variable, the time, at the value reference after the model's own (the
// FMI 3.0 glue answers fmi3GetFloat64 for it).
std::string time_variable(std::size_t reference) {
  return "    <Float64 name=\"time\" valueReference=\"" + std::to_string(reference) +
         "\" causality=\"independent\" variability=\"continuous\" unit=\"s\" "
         "description=\"simulation time\"/>\n";
}

std::string law_variables(const LawResource& r, int fmi) {
  static const LawVar vars[] = {
      {"vx", "input", "m/s", "sliding velocity of the tire at the patch centre, along x"},
      {"vy", "input", "m/s", "sliding velocity of the tire at the patch centre, along y"},
      {"omega", "input", "rad/s", "spin of the tire about the contact normal z"},
      {"N", "input", "N", "normal load (>= 0); the law is linear in it"},
      {"Fx", "output", "N", "friction force on the tire, along x"},
      {"Fy", "output", "N", "friction force on the tire, along y"},
      {"Mz", "output", "N m", "friction torque on the tire about z through the patch centre"},
      {"patch.radius", "local", "m", "patch radius R"},
      {"patch.friction", "local", "1", "friction coefficient f (f_s of a slip-speed law)"},
      {"patch.kappa", "local", "1", "lateral / longitudinal friction ratio kappa"},
      {"patch.kx", "local", "1", "pressure shift along x"},
      {"patch.ky", "local", "1", "pressure shift along y"},
      {"law.error_bound", "local", "1",
       "the exact law's certified error relative to f N and f N R (0: fractional law)"}};
  const double constants[] = {r.radius_m, r.friction, r.kappa, r.kx, r.ky, r.error_bound};
  std::string out = "  <ModelVariables>\n";
  if (fmi == 3) out += time_variable(std::size(vars));
  for (std::size_t k = 0; k < std::size(vars); ++k) {
    const LawVar& v = vars[k];
    Scalar s{v.name, v.causality, "continuous", "", v.description, "Real", v.unit, ""};
    s.reference = k;
    if (s.causality == "input") s.start = number(k == 3 ? r.normal_load_n : 0.0);
    if (s.causality == "output") s.initial = "calculated";
    if (s.causality == "local") {
      s.variability = "constant";
      s.start = number(constants[k - 7]);
    }
    out += scalar_variable(s, fmi);
  }
  return out + "  </ModelVariables>\n" + model_structure({5, 6, 7}, "1 2 3 4", 4, fmi);
}

std::string law_annotation(const ContactPatch& p, const LawFmuOptions& o, const LawResource& r) {
  std::string out = o.fmi_version == 3
                        ? "  <Annotations>\n    <Annotation type=\"org.contensou\">\n      <Patch"
                        : "  <VendorAnnotations>\n    <Tool name=\"contensou\">\n      <Patch";
  out += " radius_m=\"" + number(p.radius_m) + "\"";
  out += " reference_pressure_pa=\"" + number(p.reference_pressure_pa) + "\"";
  out += " normal_load_n=\"" + number(r.normal_load_n) + "\"";
  out += " profile=\"" + xml(o.profile_text.empty() ? describe(p.profile) : o.profile_text) + "\"";
  out += " friction=\"" + xml(friction_text(p)) + "\"";
  out += " kappa=\"" + number(p.kappa) + "\" kx=\"" + number(p.profile.kx) + "\" ky=\"" +
         number(p.profile.ky) + "\"";
  out += " law=\"" + std::string(o.law == FmuLaw::exact ? "exact" : "fractional") + "\"";
  if (r.exact)
    out += " tolerance=\"" + number(r.exact->tolerance) + "\" achieved=\"" +
           number(r.exact->achieved) + "\" table_pieces=\"" +
           std::to_string(r.exact->table.pieces()) + "\"";
  return out + (o.fmi_version == 3 ? "/>\n    </Annotation>\n  </Annotations>\n"
                                   : "/>\n    </Tool>\n  </VendorAnnotations>\n");
}

std::string law_model_description(const ContactPatch& patch, const LawFmuOptions& o,
                                  const LawResource& r) {
  const int fmi = o.fmi_version;
  const std::string id = "contensou_law";
  std::string out = header(o.model_name, r.guid, r.description, fmi);
  const std::string caps =
      fmi == 3 ? " canGetAndSetFMUState=\"false\" canSerializeFMUState=\"false\" "
                 "providesDirectionalDerivatives=\"true\" providesAdjointDerivatives=\"true\""
               : " canNotUseMemoryManagementFunctions=\"true\" canGetAndSetFMUstate=\"false\" "
                 "canSerializeFMUstate=\"false\" providesDirectionalDerivative=\"true\"";
  out += "  <ModelExchange modelIdentifier=\"" + id + "\"" + caps + "/>\n";
  out += "  <CoSimulation modelIdentifier=\"" + id + "\"" + caps +
         " canHandleVariableCommunicationStepSize=\"true\"" +
         (fmi == 3 ? " hasEventMode=\"false\"" : "") + "/>\n";
  out += unit_definitions({"m/s", "rad/s", "N", "N m", "m", "1", "s"});
  out += kLogCategories;
  out += "  <DefaultExperiment startTime=\"0\" stopTime=\"1\" stepSize=\"0.001\"/>\n";
  if (fmi == 2) out += law_annotation(patch, o, r);
  out += law_variables(r, fmi);
  if (fmi == 3) out += law_annotation(patch, o, r);
  return out + "</fmiModelDescription>\n";
}

LawResource law_resource(const ContactPatch& patch, const LawFmuOptions& o) {
  validate(patch);
  LawResource r;
  r.normal_load_n = normal_load(patch);
  r.radius_m = patch.radius_m;
  r.friction =
      patch.slip_speed_friction ? patch.slip_speed_friction->static_coefficient : patch.friction;
  r.kappa = patch.kappa;
  r.kx = patch.profile.kx;
  r.ky = patch.profile.ky;
  if (o.law == FmuLaw::exact) {
    ExactLawOptions lo;
    lo.tolerance = o.tolerance;
    lo.threads = o.threads;
    r.exact = make_exact_law(make_exact_model(patch), lo);
    r.error_bound = r.exact->achieved;
  } else {
    if (patch.slip_speed_friction)
      throw InvalidArgument("law", "fractional",
                            "takes a constant friction coefficient f; a slip-speed law f(w) needs "
                            "the exact law (--law exact)");
    r.fractional = fractional_law_from_patch(patch);
  }
  r.description = patch_description(patch, o, r.normal_load_n, r.error_bound);
  r.guid = guid_of(write_law_resource(r));  // of everything but the guid itself
  return r;
}

void write_archive(const std::string& path, std::vector<ZipEntry> entries, FmuExport& out) {
  const std::string bytes = zip_archive(entries);
  write_file_atomically(path, bytes);
  out.path = path;
  out.bytes = bytes.size();
}

}  // namespace

FmuExport export_law_fmu(const ContactPatch& patch, const std::string& path,
                         const LawFmuOptions& options) {
  if (options.model_name.empty())
    throw InvalidArgument("model_name", "empty", "must name the model");
  require_printable("model_name", options.model_name);
  require_printable("profile name", options.profile_text);
  check_fmi_version(options.fmi_version);
  const auto start = std::chrono::steady_clock::now();
  const LawResource r = law_resource(patch, options);
  FmuExport out;
  out.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.guid = r.guid;
  out.error_bound = r.error_bound;
  const std::string table = write_law_resource(r);
  out.table_bytes = table.size();
  write_archive(path,
                {{"modelDescription.xml", law_model_description(patch, options, r)},
                 {binary_path(options.fmi_version, "contensou_law"), std::string(law_fmu_binary())},
                 {std::string("resources/") + kLawResourceName, table}},
                out);
  return out;
}

#ifdef CONTENSOU_FMU_HAVE_GEAR
namespace {

const char* type_element(VariableType t) {
  return t == VariableType::real ? "Real" : t == VariableType::boolean ? "Boolean" : "String";
}

Scalar gear_scalar(const GearVariable& v, std::size_t k) {
  const Causality c = v.variable.causality;
  const bool real = v.variable.type == VariableType::real;
  Scalar s;
  s.name = v.name;
  s.reference = k;
  s.causality = c == Causality::input ? "input" : c == Causality::output ? "output" : "parameter";
  s.variability = c == Causality::parameter ? "fixed" : real ? "continuous" : "discrete";
  s.initial = c == Causality::output ? "calculated" : c == Causality::parameter ? "exact" : "";
  s.description = v.description;
  s.type = type_element(v.variable.type);
  s.unit = real ? v.unit : "";
  s.start = c == Causality::output ? "" : v.start;
  return s;
}

std::string gear_model_description(int fmi) {
  const auto& vars = gear_variables();
  std::string out = header("contensou_gear", gear_guid(),
                           "contensou one-wheel landing gear of the shimmy demo (docs/shimmy.md): "
                           "strut bending and torsion, wheel spin, the tire's contact law; "
                           "CVODE inside. Inputs the forward speed and a brake-torque command; "
                           "parameters the demo's configuration keys.",
                           fmi);
  out +=
      "  <CoSimulation modelIdentifier=\"contensou_gear\" "
      "canHandleVariableCommunicationStepSize=\"true\"" +
      std::string(fmi == 3 ? " canGetAndSetFMUState=\"false\" canSerializeFMUState=\"false\" "
                             "hasEventMode=\"false\"/>\n"
                           : " canNotUseMemoryManagementFunctions=\"true\" "
                             "canGetAndSetFMUstate=\"false\" canSerializeFMUstate=\"false\" "
                             "providesDirectionalDerivative=\"false\"/>\n");
  std::set<std::string> units;
  for (const GearVariable& v : vars)
    if (v.variable.type == VariableType::real && !v.unit.empty()) units.insert(v.unit);
  units.insert("s");
  out += unit_definitions(units);
  out += kLogCategories;
  out += "  <DefaultExperiment startTime=\"0\" stopTime=\"1\" stepSize=\"0.0005\"/>\n";
  out += "  <ModelVariables>\n";
  if (fmi == 3) out += time_variable(vars.size());
  std::vector<std::size_t> outputs;
  for (std::size_t k = 0; k < vars.size(); ++k) {
    out += scalar_variable(gear_scalar(vars[k], k), fmi);
    if (vars[k].variable.causality == Causality::output) outputs.push_back(k + 1);
  }
  return out + "  </ModelVariables>\n" + model_structure(outputs, "", 0, fmi) +
         "</fmiModelDescription>\n";
}

}  // namespace

FmuExport export_gear_fmu(const std::string& path, int fmi_version) {
  check_fmi_version(fmi_version);
  FmuExport out;
  out.guid = gear_guid();
  write_archive(path,
                {{"modelDescription.xml", gear_model_description(fmi_version)},
                 {binary_path(fmi_version, "contensou_gear"), std::string(gear_fmu_binary())}},
                out);
  return out;
}
#else
FmuExport export_gear_fmu(const std::string&, int) {
  throw std::runtime_error("this build of contensou has no gear module (SUNDIALS): no gear FMU");
}
#endif

}  // namespace contensou::fmu
