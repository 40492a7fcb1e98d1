#include "contensou/friction/csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "contensou/friction/error.hpp"

namespace contensou {
namespace {

std::string trim(const std::string& s, std::size_t* lead = nullptr) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  if (lead) *lead = b;
  return s.substr(b, e - b);
}

struct Field {
  std::string text;
  int column;  // 1-based
};

std::vector<Field> split(const std::string& line) {
  std::vector<Field> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::string raw =
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::size_t lead = 0;
    std::string t = trim(raw, &lead);
    out.push_back({t, static_cast<int>(start + lead + 1)});
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable parse_csv(const std::string& text, const std::string& name) {
  CsvTable table;
  table.file = name;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::size_t lead = 0;
    const std::string t = trim(line, &lead);
    if (t.empty() || t[0] == '#') continue;
    std::vector<Field> fields = split(line);
    if (table.header.empty()) {
      table.header_line = lineno;
      for (const Field& f : fields) {
        if (f.text.empty()) throw ParseError(name, lineno, f.column, "empty column name in header");
        for (const std::string& h : table.header)
          if (h == f.text)
            throw ParseError(name, lineno, f.column, "duplicate column '" + f.text + "'");
        table.header.push_back(f.text);
      }
      continue;
    }
    if (fields.size() != table.header.size()) {
      throw ParseError(name, lineno, fields.back().column,
                       "expected " + std::to_string(table.header.size()) + " cells, found " +
                           std::to_string(fields.size()));
    }
    CsvRow row;
    row.line = lineno;
    for (const Field& f : fields) {
      row.columns.push_back(f.column);
      if (f.text.empty()) {
        row.cells.emplace_back(std::nullopt);
        continue;
      }
      errno = 0;
      char* end = nullptr;
      const double v = std::strtod(f.text.c_str(), &end);
      if (end == f.text.c_str() || *end != '\0' || errno == ERANGE) {
        throw ParseError(name, lineno, f.column, "not a number: '" + f.text + "'");
      }
      if (!std::isfinite(v)) {
        throw ParseError(name, lineno, f.column, "non-finite value: '" + f.text + "'");
      }
      row.cells.emplace_back(v);
    }
    table.rows.push_back(std::move(row));
  }
  if (table.header.empty()) throw ParseError(name, lineno, 1, "no header row (file is empty)");
  return table;
}

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_csv(ss.str(), path);
}

}  // namespace contensou
