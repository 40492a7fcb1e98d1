/// \file
/// A reader for numeric tables in CSV as labs and spreadsheets write them: a header row naming
/// the columns, '#' comment lines, an empty cell for a missing value. Also read: a UTF-8
/// byte-order mark, CRLF or CR line ends, fields in double quotes ("" for a quote), spaces
/// around cells, trailing empty columns (Excel), unnamed columns (a pandas index), and ';' or
/// tab as separator when the header uses it (with ';' a decimal comma is read too).
/// Cells are converted to numbers only when asked for, so text in a column nobody reads is fine.
///
/// Reading is bounded (CsvLimits): a line, the number of data rows, the memory the cells take and
/// the bytes read each have a stated limit, checked as the file is read (a NUL byte too), so
/// /dev/zero, /dev/urandom or an endless pipe end in an error naming the limit, not in an
/// exhausted memory. A row takes its cells' text plus 4 bytes a cell and about 40 bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/friction/error.hpp"

namespace contensou {

/// The cells of one row in a single block of memory (their count, where each ends, their text).
/// Read like a std::vector<std::string>: size(), cells[i] (a copy), view(i) (no copy).
class CsvCells {
 public:
  CsvCells() = default;  ///< no cells
  /// The cells of `cells`, copied into one block.
  explicit CsvCells(const std::vector<std::string>& cells);
  CsvCells(const CsvCells& other);                     ///< copies the block
  CsvCells& operator=(const CsvCells& other);          ///< copies the block
  CsvCells(CsvCells&&) noexcept = default;             ///< moves the block
  CsvCells& operator=(CsvCells&&) noexcept = default;  ///< moves the block

  std::size_t size() const;                    ///< the number of cells
  bool empty() const { return size() == 0; }   ///< no cells
  std::string_view view(std::size_t i) const;  ///< cell i (0-based), no copy
  /// Cell i (0-based), a copy.
  std::string operator[](std::size_t i) const { return std::string(view(i)); }
  /// Appends a cell (copies the block: for building a row a few cells at a time).
  void push_back(std::string_view cell);
  std::vector<std::string> strings() const;  ///< every cell, copied
  /// The bytes of the block on the heap (0 for no cells).
  std::size_t heap_bytes() const;

 private:
  std::unique_ptr<char[]> block_;  ///< [count][end of each cell]... (uint32) then the text
};

/// One data row of a CsvTable.
struct CsvRow {
  int line = 0;    ///< 1-based line number in the file
  CsvCells cells;  ///< one per header column, trimmed and unquoted; "" = empty
};

/// The bounds of one read; past any of them read_csv throws ParseError naming the bound.
struct CsvLimits {
  std::size_t max_line_bytes = std::size_t{1} << 20;    ///< one line (1 MiB)
  std::size_t max_rows = 10'000'000;                    ///< data rows
  std::size_t max_lines = 100'000'000;                  ///< lines, comments and blank ones too
  std::size_t max_memory_bytes = std::size_t{1} << 30;  ///< the rows in memory (1 GiB)
  std::uint64_t max_input_bytes = std::uint64_t{4}
                                  << 30;  ///< bytes read, comments included (4 GiB)
  /// What the message past max_rows says to do ("" for: past the reader's limit of N, split the
  /// file or thin its rows).
  std::string rows_advice;
};

/// A CSV file read by read_csv: its header and its data rows, cells as text.
struct CsvTable {
  std::string file;                 ///< the path read (or the name of the in-memory data)
  int header_line = 0;              ///< 1-based line of the header
  std::vector<std::string> header;  ///< column names ("" for an unnamed column)
  std::vector<CsvRow> rows;         ///< the data rows, comments and blank lines skipped
  char separator = ',';             ///< ',', ';' or a tab, from the header
  /// In-memory data (a DataFrame's columns as cells): a row's `line` is its 1-based row number,
  /// and errors say "row N (index N-1)" instead of a file line.
  bool rows_numbered = false;

  /// Index of a column by exact name, or -1. Throws ParseError if two columns have the name.
  int column(const std::string& name) const;

  /// The number in a cell: nullopt for an empty cell. Throws ParseError
  /// "file:line: column 'name' (n): not a number: 'text'" (or "non-finite value").
  std::optional<double> number(const CsvRow& row, int column) const;

  /// An error about a cell: "file:line: column 'name' (n): message" (with rows_numbered:
  /// "source: row N (index N-1): column 'name' (n): message").
  ParseError cell_error(int line, int column, const std::string& message) const;

  /// The header's column whose name is closest to `name` (closest_name over the header).
  std::string closest_column(const std::string& name,
                             const std::vector<std::string>& exclude = {}) const;
};

/// The one of `names` closest to `name` (same name in another case, at most two edits, or the
/// same stem before '_', i.e. another unit), or "" if none is close. Names in `exclude` (those
/// the caller reads anyway), empty names and `name` itself are not suggested.
std::string closest_name(const std::vector<std::string>& names, const std::string& name,
                         const std::vector<std::string>& exclude = {});

/// Reads and validates the whole file, a block at a time. Throws ParseError (file:line: message)
/// for a missing or unreadable file, a missing header, a wrong number of cells, an unterminated
/// quote, a NUL byte, a bound of `limits` passed, or memory exhausted (naming the row reached).
CsvTable read_csv(const std::string& path, const CsvLimits& limits = {});

/// The same, from text in memory; `name` stands for the file in error messages.
CsvTable parse_csv(const std::string& text, const std::string& name, const CsvLimits& limits = {});

}  // namespace contensou
