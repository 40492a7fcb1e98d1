// A reader for numeric tables in CSV as labs and spreadsheets write them: a header row naming
// the columns, '#' comment lines, an empty cell for a missing value. Also read: a UTF-8
// byte-order mark, CRLF or CR line ends, fields in double quotes ("" for a quote), spaces
// around cells, trailing empty columns (Excel), unnamed columns (a pandas index), and ';' or
// tab as separator when the header uses it (with ';' a decimal comma is read too).
// Cells are converted to numbers only when asked for, so text in a column nobody reads is fine.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"

namespace contensou {

struct CsvRow {
  int line = 0;                    // 1-based line number in the file
  std::vector<std::string> cells;  // one per header column, trimmed and unquoted; "" = empty
};

struct CsvTable {
  std::string file;
  int header_line = 0;
  std::vector<std::string> header;  // column names ("" for an unnamed column)
  std::vector<CsvRow> rows;
  char separator = ',';  // ',', ';' or '\t', from the header
  // In-memory data (a DataFrame's columns as cells): a row's `line` is its 1-based row number,
  // and errors say "row N (index N-1)" instead of a file line.
  bool rows_numbered = false;

  // Index of a column by exact name, or -1. Throws ParseError if two columns have the name.
  int column(const std::string& name) const;

  // The number in a cell: nullopt for an empty cell. Throws ParseError
  // "file:line: column 'name' (n): not a number: 'text'" (or "non-finite value").
  std::optional<double> number(const CsvRow& row, int column) const;

  // An error about a cell: "file:line: column 'name' (n): message" (with rows_numbered:
  // "source: row N (index N-1): column 'name' (n): message").
  ParseError cell_error(int line, int column, const std::string& message) const;

  // The header's column whose name is closest to `name` (closest_name over the header).
  std::string closest_column(const std::string& name,
                             const std::vector<std::string>& exclude = {}) const;
};

// The one of `names` closest to `name` (same name in another case, at most two edits, or the
// same stem before '_', i.e. another unit), or "" if none is close. Names in `exclude` (those
// the caller reads anyway), empty names and `name` itself are not suggested.
std::string closest_name(const std::vector<std::string>& names, const std::string& name,
                         const std::vector<std::string>& exclude = {});

// Reads and validates the whole file. Throws ParseError (file:line: message) for a missing or
// unreadable file, a missing header, a wrong number of cells, an unterminated quote.
CsvTable read_csv(const std::string& path);

// The same, from text in memory; `name` stands for the file in error messages.
CsvTable parse_csv(const std::string& text, const std::string& name);

}  // namespace contensou
