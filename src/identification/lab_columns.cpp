#include "contensou/identification/lab_columns.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/units.hpp"

namespace contensou {

namespace {

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

// Channels of a tire-test file the law does not use, whose force or moment unit is expected:
// recorded, not refused (normalised names).
const std::vector<std::string> kKnownOtherChannels = {"mx", "my"};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

bool iequals(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// The quantity a bare name stands for ("vx", "Omega", "time"), if any. Time is "t" in lower
// case or "time": a capital "T" is as often a temperature.
std::optional<int> quantity_of(const std::string& stem) {
  const int time = static_cast<int>(MeasuredQuantity::t);
  for (int q = 0; q < kMeasuredQuantities; ++q)
    if (q == time ? stem == kQuantities[q].name : iequals(stem, kQuantities[q].name)) return q;
  if (iequals(stem, "time")) return time;
  return std::nullopt;
}

// A header cell split into a name and a unit: "vx [m/s]", "Mz (N m)", "omega_rpm", "Fx".
// The part after the last '_' is a unit when the part before it names a quantity or when it
// is a unit this reader knows; "run_id" and "T_tread" (T is not the time) stay one name.
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
  const Unit* unit = find_unit(unit_text);
  const std::string accepted = accepted_units(static_cast<MeasuredQuantity>(q));
  if (unit == nullptr)
    throw column_error(in, line, column.index,
                       "unit '" + unit_text + "' of " + spec.name +
                           " is not one this reader converts (" + spec.name + ": " + accepted +
                           ")");
  if (unit->dimension != spec.dimension || unit->offset_si != 0.0)
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

// "'omega [rpm]' (column 4): omega is read from 'omega_radps' (column 3)", why it is not read.
std::string read_instead(const LabHeader& in, int index, int q, const LabColumn& c) {
  return "'" + trim(in.header[index]) + "' (column " + std::to_string(index + 1) +
         "): " + kQuantities[q].name + " is read from '" + c.header + "' (column " +
         std::to_string(c.index + 1) + ")";
}

// Two columns for one quantity are an error (the same name twice: which one holds the channel?).
// A second column beside the one under the SI name is a twin (add_twin), not assigned here.
void assign(LabColumns& out, int q, int index, const LabHeader& in) {
  LabColumn& c = out.column[q];
  const std::string header = trim(in.header[index]);
  if (c.present() && header == c.header)
    throw ParseError(in.file, in.header_line, index + 1,
                     "duplicate column '" + header + "' (columns " + std::to_string(c.index + 1) +
                         " and " + std::to_string(index + 1) +
                         "): which one holds the channel? Rename one");
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

// What claims a column: a quantity, a rename to extra= or ignore=, or nothing yet.
enum class Claim { none, quantity, extra, ignore };

// A unit no quantity of the law has (a temperature, a pressure, an angle, a length, a ratio):
// a column "T [degC]" is a recorded temperature, not the time t.
bool unit_of_no_quantity(const std::string& unit_text) {
  const Unit* u = unit_text.empty() ? nullptr : find_unit(unit_text);
  if (u == nullptr) return false;
  return std::none_of(std::begin(kQuantities), std::end(kQuantities),
                      [&](const QuantitySpec& q) { return q.dimension == u->dimension; });
}

// Lower case, letters and digits only: "Force X" -> "forcex", "Fx_raw" -> "fxraw".
std::string letters_and_digits(const std::string& s) {
  std::string out;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A unit anywhere in a header cell: the trailing one split_header finds, else the first
// bracketed text that is a unit ("Fx [kN]x" holds kN).
std::string unit_in(const std::string& header, const HeaderCell& cell) {
  if (!cell.unit.empty()) return cell.unit;
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const std::size_t b = header.find(open);
    const std::size_t e = b == std::string::npos ? b : header.find(close, b + 1);
    if (e != std::string::npos && find_unit(header.substr(b + 1, e - b - 1)) != nullptr)
      return header.substr(b + 1, e - b - 1);
  }
  return "";
}

// The quantity a name not read resembles: it starts with the quantity's short name and adds at
// most two characters (Fxx, Fx1, omegaa), or it is within two edits of the SI column name
// (Fx_NN). -1 if none.
int resembled_quantity(const std::string& stem, const std::string& header) {
  const std::string n = letters_and_digits(stem);
  for (int q = 0; q < kMeasuredQuantities; ++q) {
    const std::string shortname = letters_and_digits(kQuantities[q].name);
    if (shortname.size() < 2) continue;  // "t": too short to tell a misspelling
    if (n.compare(0, shortname.size(), shortname) == 0 && n.size() <= shortname.size() + 2)
      return q;
    if (!closest_name({trim(header)}, kQuantities[q].si_column).empty()) return q;
  }
  return -1;
}

// How to keep or map a column, in the style of the front end ("--columns extra='Fx_raw'").
std::string ways_to_read(const LabHeader& in, const std::string& header, const char* quantity) {
  return "map it (" + rename_option(quantity, header, in.style) +
         "); else keep it as a recorded column (" + rename_option("extra", header, in.style) +
         ") or leave it out (" + rename_option("ignore", header, in.style) + ")";
}

// A column no quantity reads that looks like a channel whose data would be lost: refused.
void refuse_lost_channel(const LabHeader& in, int index, const HeaderCell& cell,
                         const std::string& unit) {
  const std::string header = trim(in.header[static_cast<std::size_t>(index)]);
  const Unit* u = unit.empty() ? nullptr : find_unit(unit);
  const bool force =
      u != nullptr && (u->dimension == Dimension::force || u->dimension == Dimension::moment);
  const std::string n = letters_and_digits(cell.stem);
  const bool other_channel = std::find(kKnownOtherChannels.begin(), kKnownOtherChannels.end(), n) !=
                             kKnownOtherChannels.end();
  if (other_channel) return;
  const int q = resembled_quantity(cell.stem, header);
  if (q >= 0)
    throw ParseError(in.file, in.header_line, 0,
                     "column '" + header + "' (" + std::to_string(index + 1) +
                         ") is not a column this reader knows: did you mean '" +
                         kQuantities[q].si_column + "'? (or the same with a unit: '" +
                         kQuantities[q].name + " [" + si_unit_of(kQuantities[q].dimension) +
                         "]'). If it is " + kQuantities[q].name + ", " +
                         ways_to_read(in, header, kQuantities[q].name));
  if (force)
    throw column_error(
        in, in.header_line, index,
        std::string("holds a ") + dimension_name(u->dimension) + " (" + unit +
            ") that no channel reads: if it is Fx, Fy, Fz or Mz, " +
            ways_to_read(in, header, u->dimension == Dimension::moment ? "Mz" : "Fx"));
}

// The column under the SI name of quantity q other than `index`, if the header has one that
// nothing else claims (-1 if none).
int si_named_column(const LabHeader& in, const std::vector<Claim>& claims, int q, int index) {
  for (std::size_t j = 0; j < in.header.size(); ++j)
    if (static_cast<int>(j) != index && trim(in.header[j]) == kQuantities[q].si_column &&
        (claims[j] == Claim::none || claims[j] == Claim::quantity))
      return static_cast<int>(j);
  return -1;
}

// A twin's unit ("kN" of "Fx [kN]"; "" is SI), or the refusal when it is no unit of the
// quantity: Fx_raw beside Fx_N may hold anything (a raw count, a copy of Mz).
void set_twin_unit(LabColumns::Twin& twin, const std::string& unit, const LabHeader& in, int line,
                   std::vector<ParseError>& lost) {
  const QuantitySpec& spec = kQuantities[twin.quantity];
  const Unit* u = unit.empty() ? nullptr : find_unit(unit);
  if (!unit.empty() && (u == nullptr || u->dimension != spec.dimension || u->offset_si != 0.0)) {
    lost.push_back(column_error(
        in, line, twin.index,
        std::string("is a second ") + spec.name + " beside '" + spec.si_column + "' in '" + unit +
            "', which is not a unit of " + spec.name + " (" + spec.name + ": " +
            accepted_units(static_cast<MeasuredQuantity>(twin.quantity)) +
            "): say what it holds. If it is " + spec.name + ", " + twin.remedy));
    return;
  }
  twin.unit = unit;
  twin.to_si = u == nullptr ? 1.0 : u->to_si;
}

// Column `index`, named as quantity q, beside q's column under the SI name: a twin whose rows
// must repeat the read column's (its unit from the header, or from the units row later).
void add_twin(LabColumns& out, const LabHeader& in, int q, int index, int si_index,
              const std::string& unit, std::vector<ParseError>& lost) {
  LabColumns::Twin twin;
  twin.quantity = q;
  twin.index = index;
  twin.header = trim(in.header[static_cast<std::size_t>(index)]);
  twin.remedy = ways_to_read(in, twin.header, kQuantities[q].name);
  set_twin_unit(twin, unit, in, in.header_line, lost);
  out.twins.push_back(twin);
  out.not_read.push_back("'" + twin.header + "' (column " + std::to_string(index + 1) +
                         "): " + kQuantities[q].name + " is read from '" +
                         kQuantities[q].si_column + "' (column " + std::to_string(si_index + 1) +
                         "); every row checked to hold the same value");
}

// The twins' units from the units row, where their header gives none.
void twin_units_from_row(LabColumns& out, const LabHeader& in, std::vector<ParseError>& lost) {
  for (LabColumns::Twin& twin : out.twins) {
    if (!twin.unit.empty() || twin.index >= static_cast<int>(in.first_row->size())) continue;
    const std::string text = trim((*in.first_row)[static_cast<std::size_t>(twin.index)]);
    if (!text.empty()) set_twin_unit(twin, text, in, in.first_row_line, lost);
  }
}

// The unit of a recorded column: the header's, else the units row's; converted when known.
void set_recorded_unit(RecordedColumn& r, const std::string& unit) {
  r.unit = unit;
  const Unit* u = unit.empty() ? nullptr : find_unit(unit);
  if (u == nullptr) {
    r.si_unit = unit;  // kept as written (or none)
    return;
  }
  r.si_unit = si_unit_of(u->dimension);
  r.kind = dimension_name(u->dimension);
  r.to_si = u->to_si;
  r.offset_si = u->offset_si;
}

// Every column no quantity reads: an unnamed one (a row index) and one declared ignore= are
// listed as not read; one that looks like a lost channel is refused; the rest are recorded.
void classify_other_columns(const LabHeader& in, const std::vector<Claim>& claims, LabColumns& out,
                            std::vector<ParseError>& lost) {
  for (std::size_t i = 0; i < in.header.size(); ++i) {
    const int index = static_cast<int>(i);
    const std::string header = trim(in.header[i]);
    const std::string where = "'" + header + "' (column " + std::to_string(i + 1) + ")";
    if (claims[i] == Claim::quantity) continue;
    if (header.empty()) {
      out.not_read.push_back("column " + std::to_string(i + 1) + " (unnamed)");
      continue;
    }
    if (claims[i] == Claim::ignore) {
      out.not_read.push_back(where + ": " + rename_option("ignore", header, in.style));
      continue;
    }
    const HeaderCell cell = split_header(header);
    std::string unit = unit_in(header, cell);
    if (unit.empty() && out.units_row && i < in.first_row->size()) unit = trim((*in.first_row)[i]);
    if (claims[i] != Claim::extra) {
      try {
        refuse_lost_channel(in, index, cell, unit);
      } catch (const ParseError& e) {
        lost.push_back(e);  // after the required columns' checks: the clearer message first
        continue;
      }
    }
    for (const RecordedColumn& r : out.recorded)
      if (r.header == header)
        throw ParseError(in.file, in.header_line, index + 1,
                         "duplicate column '" + header + "' (columns " +
                             std::to_string(r.index + 1) + " and " + std::to_string(i + 1) +
                             "): rename one");
    RecordedColumn r;
    r.index = index;
    r.header = header;
    r.name = cell.stem.empty() ? header : cell.stem;
    r.declared = claims[i] == Claim::extra;
    set_recorded_unit(r, unit);
    out.recorded.push_back(r);
  }
}

// A column taken for a quantity by its bare name ("T") whose units row gives a unit of no
// quantity ("degC"): a recorded variable, not the quantity.
void release_by_units_row(LabColumns& out, const LabHeader& in, std::vector<Claim>& claims) {
  for (LabColumn& c : out.column) {
    if (!c.present() || c.renamed || !c.unit_assumed ||
        c.index >= static_cast<int>(in.first_row->size()))
      continue;
    if (!unit_of_no_quantity(trim((*in.first_row)[static_cast<std::size_t>(c.index)]))) continue;
    claims[static_cast<std::size_t>(c.index)] = Claim::none;
    c = LabColumn{};
  }
}

// A column of the file that is not read but looks like a misspelt known column (or the same
// quantity in another unit) while that column is absent: the data would be silently lost.
// Columns declared extra= or ignore=, and recorded ones with a unit of no quantity ("T [degC]"),
// are not near misses.
void refuse_near_misses(const LabHeader& in, const LabColumns& cols, const ColumnRenames& renames) {
  std::vector<std::string> read = kKnownColumns;  // not suggested: the columns read anyway
  for (const LabColumn& c : cols.column)
    if (c.present()) read.push_back(in.header[static_cast<std::size_t>(c.index)]);
  for (const RecordedColumn& r : cols.recorded)
    if (r.declared || unit_of_no_quantity(r.unit)) read.push_back(in.header[r.index]);
  for (const auto& [quantity, target] : renames)
    if (iequals(quantity, "ignore"))
      read.push_back(in.header[renamed_column(in, quantity, target)]);
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
// (Columns no quantity reads are classified by classify_other_columns.)
void require_columns(const LabHeader& in, const LabColumns& cols, const ColumnRenames& renames) {
  for (MeasuredQuantity q : {MeasuredQuantity::vx, MeasuredQuantity::vy, MeasuredQuantity::omega})
    if (!cols[q].present())
      throw ParseError(in.file, in.header_line, 0,
                       std::string("missing required column '") + si_column_name(q) + "'" +
                           did_you_mean(in, si_column_name(q)) + " (or give its name: " +
                           rename_option(quantity_name(q), "NAME", in.style) + ")");
  refuse_near_misses(in, cols, renames);
  if (!in.channels_optional && !cols[MeasuredQuantity::Fx].present() &&
      !cols[MeasuredQuantity::Fy].present() && !cols[MeasuredQuantity::Mz].present())
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
  return units_of(kQuantities[static_cast<int>(q)].dimension);
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
  const bool other = iequals(q, "extra") || iequals(q, "ignore");
  if (!other && (!quantity_of(q) || iequals(q, "time")))
    throw std::invalid_argument(rename_option(q, column, style) + ": '" + q +
                                "' is not a quantity (vx, vy, omega, Fx, Fy, Mz, Fz, t; or extra, "
                                "ignore)");
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

namespace {

// The columns, and the refusals of columns that look like lost channels (thrown by the callers
// after their own checks).
LabColumns resolve(const LabHeader& in, const ColumnRenames& renames,
                   std::vector<ParseError>& lost) {
  LabColumns out;
  std::vector<Claim> claims(in.header.size());
  for (const auto& [quantity, target] : renames) {
    const int index = renamed_column(in, quantity, target);
    if (iequals(quantity, "extra") || iequals(quantity, "ignore")) {
      claims[static_cast<std::size_t>(index)] =
          iequals(quantity, "extra") ? Claim::extra : Claim::ignore;
      continue;
    }
    const int q = *quantity_of(quantity);
    assign(out, q, index, in);
    out.column[q].renamed = true;
    apply_unit(out.column[q], q, split_header(in.header[index]).unit, in, in.header_line);
    claims[static_cast<std::size_t>(index)] = Claim::quantity;
  }
  for (std::size_t i = 0; i < in.header.size(); ++i) {
    if (claims[i] != Claim::none) continue;
    const HeaderCell cell = split_header(in.header[i]);
    const std::optional<int> q = quantity_of(cell.stem);
    if (!q || unit_of_no_quantity(cell.unit)) continue;  // "T [degC]" is no time
    claims[i] = Claim::quantity;
    if (out.column[*q].renamed) {
      out.not_read.push_back(read_instead(in, static_cast<int>(i), *q, out.column[*q]));
      continue;
    }
    const int si_index = si_named_column(in, claims, *q, static_cast<int>(i));
    if (si_index >= 0 && trim(in.header[i]) != kQuantities[*q].si_column) {
      add_twin(out, in, *q, static_cast<int>(i), si_index, cell.unit, lost);
      continue;
    }
    assign(out, *q, static_cast<int>(i), in);
    apply_unit(out.column[*q], *q, cell.unit, in, in.header_line);
  }
  out.units_row = first_row_holds_units(out, in);
  if (out.units_row) release_by_units_row(out, in, claims);
  if (out.units_row) apply_units_row(out, in);
  if (out.units_row) twin_units_from_row(out, in, lost);
  classify_other_columns(in, claims, out, lost);
  return out;
}

}  // namespace

LabColumns resolve_lab_columns(const LabHeader& in, const ColumnRenames& renames) {
  std::vector<ParseError> lost;
  LabColumns out = resolve(in, renames, lost);
  if (!lost.empty()) throw lost.front();
  return out;
}

LabColumns resolve_measured_columns(const LabHeader& in, const ColumnRenames& renames) {
  if (header_looks_like_data(in))
    throw ParseError(in.file, in.header_line, 0,
                     "the first row holds numbers, not column names: the file needs a header row "
                     "(vx_mps,vy_mps,omega_radps and at least one of Fx_N,Fy_N,Mz_Nm)");
  std::vector<ParseError> lost;
  const LabColumns cols = resolve(in, renames, lost);
  require_columns(in, cols, renames);
  if (!lost.empty()) throw lost.front();
  return cols;
}

}  // namespace contensou
