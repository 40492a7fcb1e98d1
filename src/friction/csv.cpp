#include "contensou/friction/csv.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>

namespace contensou {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The separator of a table: the header's most frequent of ',', ';', tab outside quotes.
char sniff_separator(std::string_view header) {
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
void split_fields(std::string_view line, char sep, const std::string& file, int lineno,
                  std::vector<std::string>& out) {
  out.clear();
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
    out.push_back(std::move(field));
    if (i >= n) break;
    ++i;  // the separator
  }
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

// --- CsvCells: [count][end of cell 0]...[end of cell count-1] as uint32, then the text.

namespace {

std::uint32_t load_u32(const char* p) {
  std::uint32_t v = 0;
  std::memcpy(&v, p, sizeof v);
  return v;
}

void store_u32(char* p, std::uint32_t v) {
  std::memcpy(p, &v, sizeof v);
}

// A block for cells of these texts (a row is at most CsvLimits::max_line_bytes, far below 4 GiB).
std::unique_ptr<char[]> make_block(const std::vector<std::string_view>& cells) {
  if (cells.empty()) return nullptr;
  const std::size_t head = 4 * (cells.size() + 1);
  std::size_t text = 0;
  for (std::string_view c : cells) text += c.size();
  if (head + text > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("a CSV row of more than 4 GiB");
  auto block = std::make_unique_for_overwrite<char[]>(head + text);
  store_u32(block.get(), static_cast<std::uint32_t>(cells.size()));
  std::size_t end = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    std::memcpy(block.get() + head + end, cells[i].data(), cells[i].size());
    end += cells[i].size();
    store_u32(block.get() + 4 * (i + 1), static_cast<std::uint32_t>(end));
  }
  return block;
}

std::vector<std::string_view> views_of(const std::vector<std::string>& cells) {
  return {cells.begin(), cells.end()};
}

}  // namespace

CsvCells::CsvCells(const std::vector<std::string>& cells) : block_(make_block(views_of(cells))) {}

CsvCells::CsvCells(const CsvCells& other) {
  if (!other.block_) return;
  const std::size_t n = other.heap_bytes();
  block_ = std::make_unique_for_overwrite<char[]>(n);
  std::memcpy(block_.get(), other.block_.get(), n);
}

CsvCells& CsvCells::operator=(const CsvCells& other) {
  if (this != &other) *this = CsvCells(other);
  return *this;
}

std::size_t CsvCells::size() const {
  return block_ ? load_u32(block_.get()) : 0;
}

std::size_t CsvCells::heap_bytes() const {
  const std::size_t n = size();
  return n == 0 ? 0 : 4 * (n + 1) + load_u32(block_.get() + 4 * n);
}

std::string_view CsvCells::view(std::size_t i) const {
  const std::size_t n = size();
  if (i >= n)
    throw std::out_of_range("CSV cell " + std::to_string(i) + " of a row of " + std::to_string(n));
  const char* p = block_.get();
  const std::size_t begin = i == 0 ? 0 : load_u32(p + 4 * i), end = load_u32(p + 4 * (i + 1));
  return {p + 4 * (n + 1) + begin, end - begin};
}

void CsvCells::push_back(std::string_view cell) {
  std::vector<std::string_view> cells;
  for (std::size_t i = 0; i < size(); ++i) cells.push_back(view(i));
  cells.push_back(cell);
  block_ = make_block(cells);
}

std::vector<std::string> CsvCells::strings() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < size(); ++i) out.emplace_back(view(i));
  return out;
}

namespace {

// What a row costs besides its block: its CsvRow in the table and the allocator's own header.
constexpr std::size_t kRowOverhead = sizeof(CsvRow) + 16;

// "1024 MiB" for whole mebibytes, else "1000 bytes".
std::string mib(std::uint64_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// The table built a line at a time, with the row and memory bounds checked at each row.
class TableBuilder {
 public:
  TableBuilder(const std::string& name, const CsvLimits& limits) : limits_(limits) {
    table_.file = name;
  }
  int line_number() const { return lineno_; }
  const CsvLimits& limits() const { return limits_; }
  const std::string& name() const { return table_.file; }
  std::size_t rows() const { return table_.rows.size(); }

  void line(std::string_view line);

  CsvTable finish() {
    if (table_.header.empty())
      throw ParseError(table_.file, lineno_, 0, "no header row (file is empty)");
    return std::move(table_);
  }

 private:
  void header(std::string_view line);
  void add_row();

  CsvTable table_;
  const CsvLimits& limits_;
  int lineno_ = 0;
  std::size_t width_ = 0;  // header columns up to the last named one
  std::size_t memory_ = 0;
  std::vector<std::string> fields_;  // the current line's, reused
};

void TableBuilder::header(std::string_view line) {
  const std::string& name = table_.file;
  table_.separator = sniff_separator(line);
  split_fields(line, table_.separator, name, lineno_, fields_);
  width_ = fields_.size();
  while (width_ > 0 && fields_[width_ - 1].empty()) --width_;  // trailing empty columns
  if (width_ == 0) throw ParseError(name, lineno_, 1, "header row without a column name");
  fields_.resize(width_);
  table_.header = fields_;
  table_.header_line = lineno_;
}

void TableBuilder::line(std::string_view line) {
  if (static_cast<std::size_t>(lineno_) >= limits_.max_lines)
    throw ParseError(table_.file, lineno_ + 1, 0,
                     "more than " + std::to_string(limits_.max_lines) +
                         " lines, the reader's limit (comments and blank lines included)");
  ++lineno_;
  std::size_t lead = 0;
  while (lead < line.size() && is_space(line[lead])) ++lead;
  if (lead == line.size() || line[lead] == '#') return;
  if (table_.header.empty()) return header(line);
  const std::string& name = table_.file;
  split_fields(line, table_.separator, name, lineno_, fields_);
  // Cells past the header's last named column must be empty (trailing separators).
  for (std::size_t k = width_; k < fields_.size(); ++k)
    if (!fields_[k].empty())
      throw ParseError(name, lineno_, 0,
                       "cell " + std::to_string(k + 1) + " ('" + fields_[k] +
                           "') lies beyond the header's " + std::to_string(width_) + " columns");
  if (fields_.size() > width_) fields_.resize(width_);
  // A line of separators only (a spreadsheet's empty row) is skipped.
  if (std::all_of(fields_.begin(), fields_.end(), [](const std::string& f) { return f.empty(); }))
    return;
  if (fields_.size() < width_)
    throw ParseError(
        name, lineno_, 0,
        "expected " + std::to_string(width_) + " cells, found " + std::to_string(fields_.size()));
  add_row();
}

void TableBuilder::add_row() {
  const std::string& name = table_.file;
  if (table_.rows.size() >= limits_.max_rows)
    throw ParseError(name, lineno_, 0,
                     std::to_string(limits_.max_rows + 1) + " rows of data or more: " +
                         (limits_.rows_advice.empty()
                              ? "past the reader's limit of " + std::to_string(limits_.max_rows) +
                                    " rows; split the file or thin its rows"
                              : limits_.rows_advice));
  CsvRow row{lineno_, CsvCells(fields_)};
  memory_ += kRowOverhead + row.cells.heap_bytes();
  if (memory_ > limits_.max_memory_bytes)
    throw ParseError(name, lineno_, 0,
                     "the table takes more than " + mib(limits_.max_memory_bytes) +
                         " of memory after " + std::to_string(table_.rows.size()) +
                         " data rows, the reader's limit: split the file or leave out columns");
  table_.rows.push_back(std::move(row));
}

// Splits a stream of blocks into lines (at LF, CRLF or a lone CR, also across blocks) for the
// builder, checking each byte for NUL and each line's length as it goes.
class LineSplitter {
 public:
  explicit LineSplitter(TableBuilder& builder) : b_(builder) {}
  void feed(std::string_view block);
  void finish() {
    if (!pending_.empty()) b_.line(pending_);
  }

 private:
  void start(std::string_view& block);
  void take(std::string_view part, bool complete);
  [[noreturn]] void too_long() const {
    throw ParseError(b_.name(), b_.line_number() + 1, 0,
                     "a line longer than " + std::to_string(b_.limits().max_line_bytes) +
                         " bytes, the reader's limit: not a table of numbers (or no line ends)");
  }

  TableBuilder& b_;
  std::string pending_;  // the start of a line the next block goes on with
  bool started_ = false, skip_lf_ = false;
  std::uint64_t read_ = 0;
};

// The start of the text: a UTF-8 byte-order mark is dropped, UTF-16 refused.
void LineSplitter::start(std::string_view& block) {
  started_ = true;
  if (block.substr(0, 3) == "\xEF\xBB\xBF") block.remove_prefix(3);
  if (block.size() >= 2 &&
      ((block[0] == '\xFF' && block[1] == '\xFE') || (block[0] == '\xFE' && block[1] == '\xFF')))
    throw ParseError(b_.name(), 1, 1, "the file is UTF-16; save it as UTF-8 (or plain ASCII) CSV");
}

void LineSplitter::take(std::string_view part, bool complete) {
  if (pending_.size() + part.size() > b_.limits().max_line_bytes) too_long();
  if (!complete) {
    pending_.append(part);
  } else if (pending_.empty()) {
    b_.line(part);
  } else {
    pending_.append(part);
    b_.line(pending_);
    pending_.clear();
  }
}

void LineSplitter::feed(std::string_view block) {
  read_ += block.size();
  if (read_ > b_.limits().max_input_bytes)
    throw ParseError(
        b_.name(), b_.line_number() + 1, 0,
        "more than " + mib(b_.limits().max_input_bytes) + " read, the reader's limit for one file");
  if (!started_) start(block);
  std::size_t i = 0;
  if (skip_lf_ && !block.empty() && block[0] == '\n') i = 1;  // the LF of a CRLF cut in two
  skip_lf_ = false;
  std::size_t begin = i;
  for (; i < block.size(); ++i) {
    const char c = block[i];
    if (c == '\0')
      throw ParseError(b_.name(), b_.line_number() + 1,
                       static_cast<int>(pending_.size() + i - begin + 1),
                       "a NUL byte: not a text file (or a corrupt one)");
    if (c != '\n' && c != '\r') continue;
    take(block.substr(begin, i - begin), true);
    if (c == '\r') {
      if (i + 1 == block.size())
        skip_lf_ = true;
      else if (block[i + 1] == '\n')
        ++i;
    }
    begin = i + 1;
  }
  take(block.substr(begin), false);
}

// Memory exhausted while reading: an error naming the file and how far it got.
[[noreturn]] void out_of_memory(const TableBuilder& b) {
  throw ParseError(b.name(), b.line_number(), 0,
                   "out of memory after " + std::to_string(b.rows()) +
                       " data rows: the file is too large for this machine's memory (or its "
                       "memory limit, ulimit -v)");
}

}  // namespace

CsvTable parse_csv(const std::string& text, const std::string& name, const CsvLimits& limits) {
  TableBuilder builder(name, limits);
  try {
    LineSplitter lines(builder);
    lines.feed(text);
    lines.finish();
    return builder.finish();
  } catch (const std::bad_alloc&) {
    out_of_memory(builder);
  }
}

CsvTable read_csv(const std::string& path, const CsvLimits& limits) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw ParseError(path, 0, 0, "is a folder, not a CSV file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw ParseError(path, 0, 0, std::string("cannot open file (") + std::strerror(errno) + ")");
  TableBuilder builder(path, limits);
  try {
    LineSplitter lines(builder);
    std::vector<char> block(std::size_t{1} << 16);
    while (in) {
      in.read(block.data(), static_cast<std::streamsize>(block.size()));
      lines.feed(std::string_view(block.data(), static_cast<std::size_t>(in.gcount())));
    }
    if (in.bad()) throw ParseError(path, builder.line_number(), 0, "cannot read file");
    lines.finish();
    return builder.finish();
  } catch (const std::bad_alloc&) {
    out_of_memory(builder);
  }
}

}  // namespace contensou
