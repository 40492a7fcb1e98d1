// A small reader for numeric CSV files: header row, '#' comments, empty cell = missing.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace contensou {

struct CsvRow {
  int line = 0;                              // 1-based line number in the file
  std::vector<std::optional<double>> cells;  // one per header column; empty cell = nullopt
  std::vector<int> columns;                  // 1-based character column where each cell starts
};

struct CsvTable {
  std::string file;
  int header_line = 0;
  std::vector<std::string> header;  // trimmed column names
  std::vector<CsvRow> rows;

  // Index of a column by exact name, or -1.
  int column(const std::string& name) const;
};

// Reads and validates the whole file. Throws ParseError (file:line:column: message) for a
// missing file, a missing header, a wrong number of cells, a non-numeric or non-finite cell.
CsvTable read_csv(const std::string& path);

// The same, from text in memory; `name` stands for the file in error messages.
CsvTable parse_csv(const std::string& text, const std::string& name);

}  // namespace contensou
