#include "contensou/identification/lab_columns.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"

namespace contensou {

namespace {

enum class Dimension { speed, rate, force, moment, time };

struct QuantitySpec {
  const char* name;       // short name, as in --columns
  const char* si_column;  // the column's name in SI
  Dimension dimension;
};

constexpr QuantitySpec kQuantities[kMeasuredQuantities] = {
    {"vx", "vx_mps", Dimension::speed},        {"vy", "vy_mps", Dimension::speed},
    {"omega", "omega_radps", Dimension::rate}, {"Fx", "Fx_N", Dimension::force},
    {"Fy", "Fy_N", Dimension::force},          {"Mz", "Mz_Nm", Dimension::moment},
    {"Fz", "Fz_N", Dimension::force},          {"t", "t_s", Dimension::time}};

// A unit: its spellings after normalisation (lower case; spaces, '.', '*', middle dots dropped;
// a degree sign read as "deg"), its kind, the factor to SI and how reports write it.
struct UnitSpec {
  std::vector<std::string> spellings;
  Dimension dimension;
  double to_si;
  const char* display;
};

const std::vector<UnitSpec>& unit_table() {
  static const std::vector<UnitSpec> units = {
      {{"m/s", "mps", "ms-1", "ms^-1"}, Dimension::speed, 1.0, "m/s"},
      {{"km/h", "kmh", "kph", "kmph"}, Dimension::speed, 1.0 / 3.6, "km/h"},
      {{"mm/s", "mmps"}, Dimension::speed, 1e-3, "mm/s"},
      {{"rad/s", "radps", "rads-1", "rad/sec"}, Dimension::rate, 1.0, "rad/s"},
      {{"deg/s", "degps", "dps", "deg/sec"}, Dimension::rate, M_PI / 180.0, "deg/s"},
      {{"rpm", "1/min", "rev/min", "u/min", "r/min"}, Dimension::rate, 2.0 * M_PI / 60.0, "rpm"},
      {{"n"}, Dimension::force, 1.0, "N"},
      {{"kn"}, Dimension::force, 1e3, "kN"},
      {{"nm"}, Dimension::moment, 1.0, "N m"},
      {{"knm"}, Dimension::moment, 1e3, "kN m"},
      {{"nmm"}, Dimension::moment, 1e-3, "N mm"},
      {{"s", "sec"}, Dimension::time, 1.0, "s"},
      {{"ms"}, Dimension::time, 1e-3, "ms"}};
  return units;
}

const char* si_unit_of(Dimension d) {
  switch (d) {
    case Dimension::speed:
      return "m/s";
    case Dimension::rate:
      return "rad/s";
    case Dimension::force:
      return "N";
    case Dimension::moment:
      return "N m";
    case Dimension::time:
      return "s";
  }
  return "";
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::string normalise_unit(const std::string& text) {
  std::string u;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == 0xC2 && i + 1 < text.size()) {  // U+00B7 middle dot, U+00B0 degree sign
      const unsigned char d = static_cast<unsigned char>(text[i + 1]);
      if (d == 0xB7 || d == 0xB0) {
        if (d == 0xB0) u += "deg";
        ++i;
        continue;
      }
    }
    if (c == 0xE2 && i + 2 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x8B &&
        static_cast<unsigned char>(text[i + 2]) == 0x85) {  // U+22C5 dot operator
      i += 2;
      continue;
    }
    if (c == ' ' || c == '.' || c == '*' || c == '\t') continue;
    u += static_cast<char>(std::tolower(c));
  }
  return u;
}

const UnitSpec* find_unit(const std::string& text) {
  const std::string u = normalise_unit(text);
  for (const UnitSpec& spec : unit_table())
    if (std::find(spec.spellings.begin(), spec.spellings.end(), u) != spec.spellings.end())
      return &spec;
  return nullptr;
}

bool iequals(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// The quantity a bare name stands for ("vx", "Omega", "time"), if any.
std::optional<int> quantity_of(const std::string& stem) {
  for (int q = 0; q < kMeasuredQuantities; ++q)
    if (iequals(stem, kQuantities[q].name)) return q;
  if (iequals(stem, "time")) return static_cast<int>(MeasuredQuantity::t);
  return std::nullopt;
}

// A header cell split into a name and a unit: "vx [m/s]", "Mz (N m)", "omega_rpm", "Fx".
// The part after the last '_' is a unit when the part before it names a quantity or when it
// is a unit this reader knows; "run_id" stays one name.
struct HeaderCell {
  std::string stem;
  std::string unit;
};

HeaderCell split_header(const std::string& cell) {
  const std::string h = trim(cell);
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const auto b = h.rfind(open);
    if (b != std::string::npos && b > 0 && h.back() == close)
      return {trim(h.substr(0, b)), trim(h.substr(b + 1, h.size() - b - 2))};
  }
  const auto u = h.rfind('_');
  if (u != std::string::npos && u > 0 && u + 1 < h.size()) {
    const std::string stem = h.substr(0, u), unit = h.substr(u + 1);
    if (quantity_of(stem) || find_unit(unit)) return {stem, unit};
  }
  return {h, ""};
}

bool is_number(const std::string& cell) {
  const std::string c = trim(cell);
  if (c.empty()) return false;
  char* end = nullptr;
  std::strtod(c.c_str(), &end);
  return end != c.c_str() && trim(end).empty();
}

std::string column_ref(const LabHeader& in, int index) {
  return "column '" + trim(in.header[index]) + "' (" + std::to_string(index + 1) + ")";
}

// "file:line: column 'name' (n): message".
ParseError column_error(const LabHeader& in, int line, int index, const std::string& message) {
  return ParseError::in_cell(in.file, line, index + 1, trim(in.header[index]), message);
}

// Sets the unit of `column` (quantity q) from `unit_text`, or throws naming where it came from.
void apply_unit(LabColumn& column, int q, const std::string& unit_text, const LabHeader& in,
                int line) {
  const QuantitySpec& spec = kQuantities[q];
  column.si_unit = si_unit_of(spec.dimension);
  if (unit_text.empty()) {
    column.unit_assumed = true;
    return;
  }
  const UnitSpec* unit = find_unit(unit_text);
  const std::string accepted = accepted_units(static_cast<MeasuredQuantity>(q));
  if (unit == nullptr)
    throw column_error(in, line, column.index,
                       "unit '" + unit_text + "' of " + spec.name +
                           " is not one this reader converts (" + spec.name + ": " + accepted +
                           ")");
  if (unit->dimension != spec.dimension)
    throw column_error(in, line, column.index,
                       "'" + unit_text + "' is not a unit of " + spec.name + " (" + spec.name +
                           ": " + accepted + ")");
  column.unit = unit_text;
  column.to_si = unit->to_si;
  column.unit_assumed = false;
}

// The column a rename points at (the header cell, as written or trimmed), or throws.
// The header cell as written (trimmed), else the one cell whose name without its unit is it
// ("Speed" finds "Speed [km/h]").
int renamed_column(const LabHeader& in, const std::string& quantity, const std::string& target) {
  for (std::size_t i = 0; i < in.header.size(); ++i)
    if (trim(in.header[i]) == trim(target)) return static_cast<int>(i);
  int found = -1;
  for (std::size_t i = 0; i < in.header.size(); ++i)
    if (split_header(in.header[i]).stem == trim(target)) {
      if (found >= 0)
        throw ParseError(in.file, in.header_line, 0,
                         rename_option(quantity, target, in.style) + ": " + column_ref(in, found) +
                             " and " + column_ref(in, static_cast<int>(i)) +
                             " both match; give the whole header cell");
      found = static_cast<int>(i);
    }
  if (found >= 0) return found;
  std::string names;
  for (const std::string& h : in.header) names += (names.empty() ? "'" : ", '") + trim(h) + "'";
  throw ParseError(in.file, in.header_line, 0,
                   rename_option(quantity, target, in.style) + ": the header has no column '" +
                       target + "' (columns: " + names + ")");
}

// Two columns for one quantity are an error, unless one has the SI name: that one is read
// (files that log a rate in rad/s and again in rpm).
void assign(LabColumns& out, int q, int index, const LabHeader& in) {
  LabColumn& c = out.column[q];
  const std::string header = trim(in.header[index]);
  if (c.present() && !c.renamed && c.header == kQuantities[q].si_column) return;
  if (c.present() && !c.renamed && header == kQuantities[q].si_column) c = LabColumn{};
  if (c.present())
    throw ParseError(in.file, in.header_line, 0,
                     "two columns for " + std::string(kQuantities[q].name) + ": " +
                         column_ref(in, c.index) + " and " + column_ref(in, index) +
                         "; keep one, or choose one with " +
                         rename_option(kQuantities[q].name, "NAME", in.style));
  c.index = index;
  c.header = header;
}

// The first row holds units when every cell of a column read is text (at least one non-empty).
bool first_row_holds_units(const LabColumns& out, const LabHeader& in) {
  if (in.first_row == nullptr) return false;
  bool any_text = false;
  for (const LabColumn& c : out.column) {
    if (!c.present() || c.index >= static_cast<int>(in.first_row->size())) continue;
    const std::string cell = trim((*in.first_row)[c.index]);
    if (is_number(cell)) return false;
    any_text = any_text || !cell.empty();
  }
  return any_text;
}

void apply_units_row(LabColumns& out, const LabHeader& in) {
  for (int q = 0; q < kMeasuredQuantities; ++q) {
    LabColumn& c = out.column[q];
    if (!c.present() || c.index >= static_cast<int>(in.first_row->size())) continue;
    const std::string text = trim((*in.first_row)[c.index]);
    if (text.empty()) continue;
    LabColumn from_row = c;
    apply_unit(from_row, q, text, in, in.first_row_line);
    if (!c.unit_assumed && std::abs(from_row.to_si / c.to_si - 1.0) > 1e-12)
      throw column_error(in, in.first_row_line, c.index,
                         "the units row says '" + text + "' but the header says '" + c.unit + "'");
    c = from_row;
  }
}

std::string format_factor(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

const std::vector<std::string> kKnownColumns = {"vx_mps", "vy_mps", "omega_radps", "Fx_N",
                                                "Fy_N",   "Mz_Nm",  "Fz_N",        "t_s"};

// " (did you mean 'x'?)" for the header's cell closest to name, or "".
std::string did_you_mean(const LabHeader& in, const std::string& name) {
  const std::string close = closest_name(in.header, name, kKnownColumns);
  return close.empty() ? "" : " (did you mean '" + close + "'?)";
}

bool header_looks_like_data(const LabHeader& in) {
  return std::all_of(in.header.begin(), in.header.end(), [](const std::string& h) {
    char* end = nullptr;
    std::strtod(h.c_str(), &end);
    return !h.empty() && *end == '\0';
  });
}

// The index of the header cell `name`; ParseError if two cells have it (as CsvTable::column).
int header_index(const LabHeader& in, const std::string& name) {
  int found = -1;
  for (std::size_t i = 0; i < in.header.size(); ++i) {
    if (in.header[i] != name) continue;
    if (found >= 0)
      throw ParseError(in.file, in.header_line, static_cast<int>(i + 1),
                       "duplicate column '" + name + "' (columns " + std::to_string(found + 1) +
                           " and " + std::to_string(i + 1) + ")");
    found = static_cast<int>(i);
  }
  return found;
}

// A column of the file that is not read but looks like a misspelt known column (or the same
// quantity in another unit) while that column is absent: the data would be silently lost.
void refuse_near_misses(const LabHeader& in, const LabColumns& cols) {
  std::vector<std::string> read = kKnownColumns;  // not suggested: the columns read anyway
  for (const LabColumn& c : cols.column)
    if (c.present()) read.push_back(in.header[static_cast<std::size_t>(c.index)]);
  for (int q = 0; q < kMeasuredQuantities; ++q) {
    if (cols.column[q].present()) continue;
    const std::string k = kQuantities[q].si_column;
    const std::string close = closest_name(in.header, k, read);
    if (close.empty()) continue;
    const int col = header_index(in, close);
    throw ParseError(in.file, in.header_line, 0,
                     "column '" + close + "' (" + std::to_string(col + 1) +
                         ") is not a column this reader knows: did you mean '" + k +
                         "'? (columns: vx_mps, vy_mps, omega_radps, Fx_N, Fy_N, Mz_Nm, Fz_N, t_s, "
                         "or the same with a unit: 'vx [km/h]', omega_rpm; or map it: " +
                         rename_option(kQuantities[q].name, "NAME", in.style) + ")");
  }
}

// A missing required column, a near miss, no channel: refused naming the header line.
void require_columns(const LabHeader& in, const LabColumns& cols) {
  for (MeasuredQuantity q : {MeasuredQuantity::vx, MeasuredQuantity::vy, MeasuredQuantity::omega})
    if (!cols[q].present())
      throw ParseError(in.file, in.header_line, 0,
                       std::string("missing required column '") + si_column_name(q) + "'" +
                           did_you_mean(in, si_column_name(q)) + " (or give its name: " +
                           rename_option(quantity_name(q), "NAME", in.style) + ")");
  refuse_near_misses(in, cols);
  if (!cols[MeasuredQuantity::Fx].present() && !cols[MeasuredQuantity::Fy].present() &&
      !cols[MeasuredQuantity::Mz].present())
    throw ParseError(in.file, in.header_line, 0, "no measured channel (need Fx_N, Fy_N or Mz_Nm)");
}

}  // namespace

const char* quantity_name(MeasuredQuantity q) {
  return kQuantities[static_cast<int>(q)].name;
}

const char* si_column_name(MeasuredQuantity q) {
  return kQuantities[static_cast<int>(q)].si_column;
}

std::string accepted_units(MeasuredQuantity q) {
  std::string s;
  for (const UnitSpec& u : unit_table())
    if (u.dimension == kQuantities[static_cast<int>(q)].dimension)
      s += (s.empty() ? "" : ", ") + std::string(u.display);
  return s;
}

std::string LabColumn::description() const {
  std::string s = "'" + header + "' (column " + std::to_string(index + 1) + ")";
  if (unit_assumed) return s + ", no unit given: read as " + si_unit;
  if (to_si == 1.0) return s + " in " + si_unit;
  return s + " in " + unit + ", x " + format_factor(to_si) + " to " + si_unit;
}

std::vector<std::string> LabColumns::notes() const {
  std::vector<std::string> notes;
  for (int q = 0; q < kMeasuredQuantities; ++q) {
    const LabColumn& c = column[q];
    if (!c.present() || (c.header == kQuantities[q].si_column && !c.renamed)) continue;
    notes.push_back(std::string(kQuantities[q].si_column) + " from " + c.description());
  }
  return notes;
}

void add_column_rename(ColumnRenames& renames, const std::string& quantity,
                       const std::string& column, KeyStyle style) {
  const std::string q = trim(quantity);
  if (!quantity_of(q) || iequals(q, "time"))
    throw std::invalid_argument(rename_option(q, column, style) + ": '" + q +
                                "' is not a quantity (vx, vy, omega, Fx, Fy, Mz, Fz, t)");
  renames.emplace_back(q, trim(column));
}

ColumnRenames parse_column_renames(const std::string& text, KeyStyle style) {
  ColumnRenames renames;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string part = trim(text.substr(start, end - start));
    start = end + 1;
    if (part.empty()) continue;
    const auto eq = part.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument(std::string(style == KeyStyle::python ? "columns" : "--columns") +
                                  " '" + part + "': expected QUANTITY=COLUMN, e.g. vx=Speed");
    add_column_rename(renames, part.substr(0, eq), part.substr(eq + 1), style);
  }
  return renames;
}

LabColumns resolve_lab_columns(const LabHeader& in, const ColumnRenames& renames) {
  LabColumns out;
  std::vector<bool> taken(in.header.size(), false);
  for (const auto& [quantity, target] : renames) {
    const int q = *quantity_of(quantity);
    const int index = renamed_column(in, quantity, target);
    assign(out, q, index, in);
    out.column[q].renamed = true;
    apply_unit(out.column[q], q, split_header(in.header[index]).unit, in, in.header_line);
    taken[index] = true;
  }
  for (std::size_t i = 0; i < in.header.size(); ++i) {
    if (taken[i]) continue;
    const HeaderCell cell = split_header(in.header[i]);
    const std::optional<int> q = quantity_of(cell.stem);
    if (!q || out.column[*q].renamed) continue;
    assign(out, *q, static_cast<int>(i), in);
    if (out.column[*q].index == static_cast<int>(i))
      apply_unit(out.column[*q], *q, cell.unit, in, in.header_line);
  }
  out.units_row = first_row_holds_units(out, in);
  if (out.units_row) apply_units_row(out, in);
  return out;
}

LabColumns resolve_measured_columns(const LabHeader& in, const ColumnRenames& renames) {
  if (header_looks_like_data(in))
    throw ParseError(in.file, in.header_line, 0,
                     "the first row holds numbers, not column names: the file needs a header row "
                     "(vx_mps,vy_mps,omega_radps and at least one of Fx_N,Fy_N,Mz_Nm)");
  const LabColumns cols = resolve_lab_columns(in, renames);
  require_columns(in, cols);
  return cols;
}

}  // namespace contensou
