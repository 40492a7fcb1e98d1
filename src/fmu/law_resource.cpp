#include "law_resource.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/friction/piecewise_chebyshev.hpp"

namespace contensou::fmu {

namespace {

constexpr const char* kMagic = "contensou-fmu-law 1";
// No table the exporter writes comes near this (the seed tire's is about 1e4 numbers); a larger
// count is a damaged file, refused before anything is allocated for it.
constexpr std::size_t kMostValues = 50'000'000;

// ---- writing ----

void put(std::ostringstream& out, const char* name, const double* v, std::size_t n) {
  out << name << ' ' << n;
  char buf[40];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, " %a", v[i]);
    out << buf;
  }
  out << '\n';
}
void put(std::ostringstream& out, const char* name, const std::vector<double>& v) {
  put(out, name, v.data(), v.size());
}
void put(std::ostringstream& out, const char* name, std::initializer_list<double> v) {
  put(out, name, v.begin(), v.size());
}
void put_text(std::ostringstream& out, const char* name, const std::string& text) {
  std::string line = text;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  out << "text " << name << ' ' << line << '\n';
}

void put_table(std::ostringstream& out, const std::string& prefix, const PiecewiseChebyshev& t) {
  put(out, (prefix + "_shape").c_str(), {double(t.functions), double(t.degree)});
  put(out, (prefix + "_breaks").c_str(), t.breaks);
  put(out, (prefix + "_coefficients").c_str(), t.coefficients);
  put(out, (prefix + "_slope_at_start").c_str(), t.slope_at_start);
  put(out, (prefix + "_slope_at_end").c_str(), t.slope_at_end);
}

void put_exact(std::ostringstream& out, const ExactLaw& law) {
  put(out, "exact",
      {law.radius, law.load_area, law.tolerance, law.achieved, law.reached ? 1.0 : 0.0,
       double(law.samples)});
  const ExactLawParameters<double>& p = law.parameters;
  put(out, "exact_parameters", {p.pressure, p.friction, p.kappa, p.kx, p.ky});
  if (p.slip_speed)
    put(out, "exact_slip_speed",
        {p.slip_speed->static_coefficient, p.slip_speed->kinetic_coefficient,
         p.slip_speed->reference_speed, p.slip_speed->exponent});
  put_table(out, "table", law.table);
  if (!law.falling) return;
  const SlipSpeedTable& s = *law.falling;
  put(out, "falling", {s.exponent, double(s.degree_z), s.tail, double(s.octaves)});
  put_table(out, "falling_pieces", s.pieces);
  std::vector<double> block(s.block.begin(), s.block.end());
  put(out, "falling_block", block);
  put(out, "falling_coefficients", s.coefficients);
}

// ---- reading ----

struct Record {
  int line = 0;
  std::vector<double> values;
};

class Reader {
 public:
  Reader(const std::string& text, std::string source) : source_(std::move(source)) { parse(text); }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw ParseError(source_, line, 0, message);
  }

  bool has(const std::string& name) const { return numbers_.count(name) != 0; }

  // The record `name` with exactly `count` values (any count if count < 0).
  const Record& numbers(const std::string& name, long count = -1) {
    used_.insert(name);
    const auto it = numbers_.find(name);
    if (it == numbers_.end()) fail(0, "no record '" + name + "'");
    if (count >= 0 && it->second.values.size() != static_cast<std::size_t>(count))
      fail(it->second.line, "'" + name + "' has " + std::to_string(it->second.values.size()) +
                                " values, expected " + std::to_string(count));
    return it->second;
  }

  std::pair<int, std::string> text(const std::string& name) {
    used_.insert("text " + name);
    const auto it = texts_.find(name);
    if (it == texts_.end()) fail(0, "no record 'text " + name + "'");
    return it->second;
  }

  // Every record was read: one the reader does not know is a file of another version.
  void check_all_used() const {
    for (const auto& [name, r] : numbers_)
      if (!used_.count(name)) fail(r.line, "unknown record '" + name + "'");
    for (const auto& [name, t] : texts_)
      if (!used_.count("text " + name)) fail(t.first, "unknown record 'text " + name + "'");
  }

 private:
  void parse(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (number == 1) {
        if (line != kMagic)
          fail(1, "not a law FMU resource: the first line must be '" + std::string(kMagic) + "'");
        continue;
      }
      if (line.empty() || line[0] == '#') continue;
      parse_line(line, number);
    }
    if (number == 0) fail(0, "empty file: not a law FMU resource");
  }

  void parse_line(const std::string& line, int number) {
    const std::size_t space = line.find(' ');
    const std::string name = line.substr(0, space);
    if (name == "text") {
      const std::size_t second = line.find(' ', space + 1);
      if (space == std::string::npos || second == std::string::npos)
        fail(number, "a text record needs a name and a value");
      const std::string key = line.substr(space + 1, second - space - 1);
      if (!texts_.emplace(key, std::pair{number, line.substr(second + 1)}).second)
        fail(number, "a second record 'text " + key + "'");
      return;
    }
    Record r{number, {}};
    const char* p = line.c_str() + (space == std::string::npos ? line.size() : space);
    char* end = nullptr;
    errno = 0;
    const long long count = std::strtoll(p, &end, 10);
    if (end == p || count < 0 || static_cast<unsigned long long>(count) > kMostValues)
      fail(number, "'" + name + "': the count must be a number in [0, " +
                       std::to_string(kMostValues) + "]");
    r.values.reserve(static_cast<std::size_t>(count));
    for (p = end; r.values.size() < static_cast<std::size_t>(count); p = end) {
      const double v = std::strtod(p, &end);
      if (end == p)
        fail(number, "'" + name + "': value " + std::to_string(r.values.size() + 1) + " of " +
                         std::to_string(count) + " is missing or not a number");
      if (!std::isfinite(v))
        fail(number,
             "'" + name + "': value " + std::to_string(r.values.size() + 1) + " is not finite");
      r.values.push_back(v);
    }
    while (*p == ' ' || *p == '\t') ++p;
    if (*p) fail(number, "'" + name + "': more values than its count " + std::to_string(count));
    if (!numbers_.emplace(name, std::move(r)).second)
      fail(number, "a second record '" + name + "'");
  }

  std::string source_;
  std::map<std::string, Record> numbers_;
  std::map<std::string, std::pair<int, std::string>> texts_;
  std::set<std::string> used_;
};

int whole(Reader& in, const Record& r, std::size_t i, int lo, int hi, const char* what) {
  const double v = r.values[i];
  if (!(v >= lo && v <= hi && v == std::floor(v)))
    in.fail(r.line, std::string(what) + " = " + format_value(v) + ": must be a whole number in [" +
                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v);
}

// A table's pieces: shape, breaks increasing from -1 to 1, the coefficients' and slopes' counts
// (`coefficients` false: the falling part's shared pieces, which hold none).
PiecewiseChebyshev read_table(Reader& in, const std::string& prefix, int functions,
                              bool coefficients) {
  PiecewiseChebyshev t;
  const Record& shape = in.numbers(prefix + "_shape", 2);
  t.functions = whole(in, shape, 0, functions, functions, (prefix + " functions").c_str());
  t.degree = whole(in, shape, 1, 4, 32, (prefix + " degree").c_str());
  const Record& breaks = in.numbers(prefix + "_breaks");
  t.breaks = breaks.values;
  if (t.breaks.size() < 2 || t.breaks.size() > 65536 || t.breaks.front() != -1.0 ||
      t.breaks.back() != 1.0)
    in.fail(breaks.line, prefix + "_breaks: 2 to 65536 piece ends from -1 to 1 expected");
  for (std::size_t k = 1; k < t.breaks.size(); ++k)
    if (!(t.breaks[k] > t.breaks[k - 1]))
      in.fail(breaks.line, prefix + "_breaks: not increasing at end " + std::to_string(k + 1));
  const auto pieces = static_cast<long>(t.breaks.size() - 1);
  const long count = coefficients ? pieces * (t.degree + 1) * functions : 0;
  t.coefficients = in.numbers(prefix + "_coefficients", count).values;
  const long slopes = coefficients ? functions : 0;
  t.slope_at_start = in.numbers(prefix + "_slope_at_start", slopes).values;
  t.slope_at_end = in.numbers(prefix + "_slope_at_end", slopes).values;
  index_pieces(t);
  return t;
}

SlipSpeedTable read_falling(Reader& in) {
  SlipSpeedTable s;
  const Record& head = in.numbers("falling", 4);
  s.exponent = head.values[0];
  if (!(s.exponent > 0.0)) in.fail(head.line, "falling exponent must be > 0");
  s.degree_z = whole(in, head, 1, kSlipDegreeZ, kSlipDegreeZ, "falling degree_z");
  s.tail = head.values[2];
  s.octaves = whole(in, head, 3, 0, 1000, "falling octaves");
  s.pieces = read_table(in, "falling_pieces", kLawFunctions * (kSlipDegreeZ + 1), false);
  const Record& block =
      in.numbers("falling_block", static_cast<long>(s.octaves) * s.pieces.pieces());
  const Record& coefficients = in.numbers("falling_coefficients");
  s.coefficients = coefficients.values;
  const std::size_t size = static_cast<std::size_t>(kLawFunctions) * (kSlipDegreeZ + 1) *
                           static_cast<std::size_t>(s.pieces.degree + 1);
  for (std::size_t i = 0; i < block.values.size(); ++i) {
    const double v = block.values[i];
    if (!(v >= 0.0 && v == std::floor(v) && v + double(size) <= double(s.coefficients.size())))
      in.fail(block.line, "falling_block: offset " + std::to_string(i + 1) + " = " +
                              format_value(v) + " is not a block of falling_coefficients");
    s.block.push_back(static_cast<std::uint32_t>(v));
  }
  return s;
}

ExactLaw read_exact(Reader& in) {
  ExactLaw law;
  const Record& head = in.numbers("exact", 6);
  law.radius = head.values[0];
  law.load_area = head.values[1];
  law.tolerance = head.values[2];
  law.achieved = head.values[3];
  law.reached = head.values[4] != 0.0;
  law.samples = whole(in, head, 5, 0, 2'000'000'000, "exact samples");
  if (!(law.radius > 0.0 && law.load_area > 0.0 && law.achieved >= 0.0))
    in.fail(head.line, "exact: radius, load area and achieved must be positive");
  const Record& p = in.numbers("exact_parameters", 5);
  law.parameters.pressure = p.values[0];
  law.parameters.friction = p.values[1];
  law.parameters.kappa = p.values[2];
  law.parameters.kx = p.values[3];
  law.parameters.ky = p.values[4];
  if (!(law.parameters.pressure > 0.0 && law.parameters.friction >= 0.0 &&
        law.parameters.kappa > 0.0))
    in.fail(p.line, "exact_parameters: pressure and kappa must be > 0, friction >= 0");
  if (in.has("exact_slip_speed")) {
    const Record& s = in.numbers("exact_slip_speed", 4);
    law.parameters.slip_speed =
        SlipSpeedFriction<double>{s.values[0], s.values[1], s.values[2], s.values[3]};
    if (!(s.values[0] >= 0.0 && s.values[1] >= 0.0 && s.values[2] > 0.0 && s.values[3] > 0.0))
      in.fail(s.line, "exact_slip_speed: f_s, f_k >= 0 and w_s, delta > 0 expected");
  }
  law.table = read_table(in, "table", kLawFunctions, true);
  if (in.has("falling")) law.falling = read_falling(in);
  if (law.parameters.slip_speed.has_value() != law.falling.has_value())
    in.fail(0, "a slip-speed law needs both exact_slip_speed and its falling table");
  if (law.falling && law.falling->exponent != law.parameters.slip_speed->exponent)
    in.fail(0, "the falling table's exponent is not the slip-speed law's");
  return law;
}

FractionalLaw<double> read_fractional(Reader& in) {
  const Record& r = in.numbers("fractional", 12);
  const std::vector<double>& v = r.values;
  FractionalLaw<double> law;
  law.F0 = v[0];
  law.M0 = v[1];
  law.a = v[2];
  law.m = v[3];
  law.kx = v[4];
  law.ky = v[5];
  law.kappa = v[6];
  law.c = v[7];
  law.Mk = v[8];
  law.a_k = v[9];
  law.radius = v[10];
  law.regularization_speed = v[11];
  try {
    validate(law);
  } catch (const std::exception& e) {
    in.fail(r.line, std::string("fractional: ") + e.what());
  }
  return law;
}

}  // namespace

std::string write_law_resource(const LawResource& r) {
  std::ostringstream out;
  out << kMagic << '\n';
  out << "# The friction law of a contensou FMU (src/fmu/law_resource.hpp): written at export,\n"
         "# read at instantiation. Numbers in hexadecimal floating point (%a).\n";
  put_text(out, "guid", r.guid);
  put_text(out, "description", r.description);
  put(out, "normal_load", {r.normal_load_n});
  put(out, "patch", {r.radius_m, r.friction, r.kappa, r.kx, r.ky});
  put(out, "error_bound", {r.error_bound});
  if (r.exact) {
    put_text(out, "law", "exact");
    put_exact(out, *r.exact);
  } else if (r.fractional) {
    const FractionalLaw<double>& f = *r.fractional;
    put_text(out, "law", "fractional");
    put(out, "fractional",
        {f.F0, f.M0, f.a, f.m, f.kx, f.ky, f.kappa, f.c, f.Mk, f.a_k, f.radius,
         f.regularization_speed});
  }
  return out.str();
}

LawResource read_law_resource(const std::string& text, const std::string& source) {
  Reader in(text, source);
  LawResource r;
  r.guid = in.text("guid").second;
  r.description = in.text("description").second;
  const Record& load = in.numbers("normal_load", 1);
  r.normal_load_n = load.values[0];
  if (!(r.normal_load_n >= 0.0)) in.fail(load.line, "normal_load must be >= 0");
  const Record& patch = in.numbers("patch", 5);
  r.radius_m = patch.values[0];
  r.friction = patch.values[1];
  r.kappa = patch.values[2];
  r.kx = patch.values[3];
  r.ky = patch.values[4];
  r.error_bound = in.numbers("error_bound", 1).values[0];
  const auto [line, law] = in.text("law");
  if (law == "exact")
    r.exact = read_exact(in);
  else if (law == "fractional")
    r.fractional = read_fractional(in);
  else
    in.fail(line, "law '" + law + "': exact or fractional expected");
  in.check_all_used();
  return r;
}

}  // namespace contensou::fmu
