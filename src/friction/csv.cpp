#include "contensou/friction/csv.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace contensou {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// Lines split at LF, CRLF or a lone CR.
std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string cur;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      lines.push_back(cur);
      cur.clear();
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

// The separator of a table: the header's most frequent of ',', ';', tab outside quotes.
char sniff_separator(const std::string& header) {
  int n[3] = {0, 0, 0};
  bool quoted = false;
  for (char c : header) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    n[0] += c == ',';
    n[1] += c == ';';
    n[2] += c == '\t';
  }
  if (n[1] > n[0] && n[1] >= n[2]) return ';';
  if (n[2] > n[0] && n[2] > n[1]) return '\t';
  return ',';
}

// The fields of a line: separated by `sep` outside double quotes, trimmed, unquoted.
std::vector<std::string> split_fields(const std::string& line, char sep, const std::string& file,
                                      int lineno) {
  std::vector<std::string> out;
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (true) {
    while (i < n && line[i] != sep && is_space(line[i])) ++i;
    std::string field;
    if (i < n && line[i] == '"') {
      const std::size_t open = i++;
      bool closed = false;
      while (i < n) {
        if (line[i] == '"') {
          if (i + 1 < n && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          closed = true;
          break;
        }
        field += line[i++];
      }
      if (!closed) throw ParseError(file, lineno, static_cast<int>(open + 1), "unterminated quote");
      while (i < n && line[i] != sep && is_space(line[i])) ++i;
      if (i < n && line[i] != sep)
        throw ParseError(file, lineno, static_cast<int>(i + 1),
                         "text after a closing quote (a quote inside a field is written \"\")");
    } else {
      const std::size_t start = i;
      while (i < n && line[i] != sep) ++i;
      std::size_t end = i;
      while (end > start && is_space(line[end - 1])) --end;
      field = line.substr(start, end - start);
    }
    out.push_back(field);
    if (i >= n) break;
    ++i;  // the separator
  }
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Levenshtein distance.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> d(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = d[0];
    d[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = d[j];
      d[j] = std::min({d[j] + 1, d[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return d[b.size()];
}

std::string stem(const std::string& s) {
  return lower(s.substr(0, s.find('_')));
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  int found = -1;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] != name) continue;
    if (found >= 0)
      throw ParseError(file, header_line, static_cast<int>(i + 1),
                       "duplicate column '" + name + "' (columns " + std::to_string(found + 1) +
                           " and " + std::to_string(i + 1) + ")");
    found = static_cast<int>(i);
  }
  return found;
}

ParseError CsvTable::cell_error(int line, int col, const std::string& message) const {
  if (rows_numbered)
    return ParseError(file, 0, 0,
                      "row " + std::to_string(line) + " (index " + std::to_string(line - 1) +
                          "): column '" + header[static_cast<std::size_t>(col)] + "' (" +
                          std::to_string(col + 1) + "): " + message);
  return ParseError::in_cell(file, line, col + 1, header[static_cast<std::size_t>(col)], message);
}

std::optional<double> CsvTable::number(const CsvRow& row, int col) const {
  std::string text = row.cells[static_cast<std::size_t>(col)];
  if (text.empty()) return std::nullopt;
  if (separator == ';' && text.find(',') != std::string::npos &&
      text.find('.') == std::string::npos)
    std::replace(text.begin(), text.end(), ',', '.');  // decimal comma
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || end != text.c_str() + text.size())  // also a NUL inside
    throw cell_error(row.line, col,
                     "not a number: '" + row.cells[static_cast<std::size_t>(col)] + "'");
  if (!std::isfinite(v) || errno == ERANGE) {
    if (errno == ERANGE && std::isfinite(v))  // underflow to a subnormal or zero is a number
      return v;
    throw cell_error(row.line, col,
                     "non-finite value '" + row.cells[static_cast<std::size_t>(col)] + "'");
  }
  return v;
}

std::string closest_name(const std::vector<std::string>& names, const std::string& name,
                         const std::vector<std::string>& exclude) {
  std::string best;
  std::size_t best_d = 3;
  for (const std::string& h : names) {
    if (h.empty() || h == name || std::find(exclude.begin(), exclude.end(), h) != exclude.end())
      continue;
    const std::size_t d =
        lower(h) == lower(name) ? 0 : (stem(h) == stem(name) ? 2 : edit_distance(h, name));
    if (d < best_d) {
      best_d = d;
      best = h;
    }
  }
  return best;
}

std::string CsvTable::closest_column(const std::string& name,
                                     const std::vector<std::string>& exclude) const {
  return closest_name(header, name, exclude);
}

CsvTable parse_csv(const std::string& text_in, const std::string& name) {
  CsvTable table;
  table.file = name;
  std::string text = text_in;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // UTF-8 byte-order mark
  if (text.size() >= 2 &&
      ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF')))
    throw ParseError(name, 1, 1, "the file is UTF-16; save it as UTF-8 (or plain ASCII) CSV");
  const std::vector<std::string> lines = split_lines(text);
  int lineno = 0;
  std::size_t width = 0;  // header columns up to the last named one
  for (const std::string& line : lines) {
    ++lineno;
    if (const std::size_t nul = line.find('\0'); nul != std::string::npos)
      throw ParseError(name, lineno, static_cast<int>(nul + 1),
                       "a NUL byte: not a text file (or a corrupt one)");
    std::size_t lead = 0;
    while (lead < line.size() && is_space(line[lead])) ++lead;
    if (lead == line.size() || line[lead] == '#') continue;
    if (table.header.empty()) {
      table.separator = sniff_separator(line);
      std::vector<std::string> names = split_fields(line, table.separator, name, lineno);
      width = names.size();
      while (width > 0 && names[width - 1].empty()) --width;  // trailing empty columns
      if (width == 0) throw ParseError(name, lineno, 1, "header row without a column name");
      names.resize(width);
      table.header = names;
      table.header_line = lineno;
      continue;
    }
    std::vector<std::string> fields = split_fields(line, table.separator, name, lineno);
    // Cells past the header's last named column must be empty (trailing separators).
    for (std::size_t k = width; k < fields.size(); ++k)
      if (!fields[k].empty())
        throw ParseError(name, lineno, 0,
                         "cell " + std::to_string(k + 1) + " ('" + fields[k] +
                             "') lies beyond the header's " + std::to_string(width) + " columns");
    if (fields.size() > width) fields.resize(width);
    // A line of separators only (a spreadsheet's empty row) is skipped.
    if (std::all_of(fields.begin(), fields.end(), [](const std::string& f) { return f.empty(); }))
      continue;
    if (fields.size() < width)
      throw ParseError(
          name, lineno, 0,
          "expected " + std::to_string(width) + " cells, found " + std::to_string(fields.size()));
    table.rows.push_back({lineno, std::move(fields)});
  }
  if (table.header.empty()) throw ParseError(name, lineno, 0, "no header row (file is empty)");
  return table;
}

CsvTable read_csv(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ParseError(path, 0, 0, "is a folder, not a CSV file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw ParseError(path, 0, 0, std::string("cannot open file (") + std::strerror(errno) + ")");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw ParseError(path, 0, 0, "cannot read file");
  return parse_csv(ss.str(), path);
}

}  // namespace contensou
