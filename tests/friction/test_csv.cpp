#include <gtest/gtest.h>

#include "temp_files.hpp"

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"

#include <cstdio>
#include <fstream>

using namespace contensou;

namespace {

std::vector<std::optional<double>> numbers(const CsvTable& t, std::size_t row) {
  std::vector<std::optional<double>> out;
  for (std::size_t c = 0; c < t.header.size(); ++c)
    out.push_back(t.number(t.rows[row], static_cast<int>(c)));
  return out;
}

// Parses the text and reads every cell as a number; expects a ParseError.
void expect_parse_error(const std::string& text, int line, int column, const std::string& part) {
  try {
    const CsvTable t = parse_csv(text, "f.csv");
    for (std::size_t r = 0; r < t.rows.size(); ++r) numbers(t, r);
    FAIL() << "no error for: " << text;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("f.csv:", 0), 0u) << e.what();
  }
}

}  // namespace

TEST(Csv, ParsesCommentsEmptyCellsAndAnyColumnOrder) {
  const CsvTable t = parse_csv("# comment\nb, a\n 1.5 ,\n#x\n-2,3e2\n", "mem.csv");
  ASSERT_EQ(t.header.size(), 2u);
  EXPECT_EQ(t.column("a"), 1);
  EXPECT_EQ(t.column("b"), 0);
  EXPECT_EQ(t.column("c"), -1);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].line, 3);
  EXPECT_DOUBLE_EQ(*t.number(t.rows[0], 0), 1.5);
  EXPECT_FALSE(t.number(t.rows[0], 1).has_value());
  EXPECT_DOUBLE_EQ(*t.number(t.rows[1], 1), 300.0);
}

// The same table as a spreadsheet, a lab's script and a European Excel would write it.
TEST(Csv, ReadsWhatLabsAndSpreadsheetsWrite) {
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"plain", "a,b\n1.5,-2\n,3\n"},
      {"BOM + CRLF",
       "\xEF\xBB\xBF"
       "a,b\r\n1.5,-2\r\n,3\r\n"},
      {"CR only", "a,b\r1.5,-2\r,3\r"},
      {"quoted", "\"a\",\"b\"\n\"1.5\",\"-2\"\n\"\",\"3\"\n"},
      {"spaces", "  a ,  \"b\"  \n 1.5 , -2 \n , 3\n"},
      {"trailing columns", "a,b,,\n1.5,-2,,\n,3,,\n,,,\n"},
      {"semicolon, decimal comma", "a;b\n1,5;-2\n;3\n"},
      {"tab", "a\tb\n1.5\t-2\n\t3\n"},
      {"no final newline", "a,b\n1.5,-2\n,3"},
  };
  for (const auto& [what, text] : variants) {
    SCOPED_TRACE(what);
    const CsvTable t = parse_csv(text, "lab.csv");
    ASSERT_EQ(t.header, (std::vector<std::string>{"a", "b"}));
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(*t.number(t.rows[0], 0), 1.5);
    EXPECT_EQ(*t.number(t.rows[0], 1), -2.0);
    EXPECT_FALSE(t.number(t.rows[1], 0).has_value());
    EXPECT_EQ(*t.number(t.rows[1], 1), 3.0);
  }
}

TEST(Csv, UnnamedAndTextColumnsAreReadOnlyWhenAskedFor) {
  // A pandas index (unnamed first column) and a text column nobody reads.
  const CsvTable t = parse_csv(",x,note\n0,1.5,\"ok, fine\"\n1,2,\"said \"\"hi\"\"\"\n", "p.csv");
  EXPECT_EQ(t.column("x"), 1);
  EXPECT_EQ(*t.number(t.rows[1], 1), 2.0);
  EXPECT_EQ(t.rows[1].cells[2], "said \"hi\"");
  EXPECT_THROW(t.number(t.rows[0], 2), ParseError);
}

TEST(Csv, NamesLineAndColumnOfBadCells) {
  expect_parse_error("a,b\n1,x2\n", 2, 2, "column 'b' (2): not a number: 'x2'");
  expect_parse_error("a,b\n1,2\n1,nan\n", 3, 2, "f.csv:3: column 'b' (2): non-finite value 'nan'");
  expect_parse_error("a,b\n1,1e999\n", 2, 2, "non-finite value '1e999'");
  expect_parse_error("a,b\n1,2,3\n", 2, 0, "cell 3 ('3') lies beyond the header's 2 columns");
  expect_parse_error("a,b\n1\n", 2, 0, "expected 2 cells, found 1");
  expect_parse_error("# only a comment\n", 1, 0, "no header");
  expect_parse_error("", 0, 0, "no header");
  expect_parse_error("a,b\n1,\"2\n", 2, 3, "unterminated quote");
  expect_parse_error("a,b\n1,\"2\"x\n", 2, 6, "text after a closing quote");
  expect_parse_error(
      "\xFF\xFE"
      "a\0,\0b\0",
      1, 1, "UTF-16");
}

TEST(Csv, DuplicateColumnIsAnErrorWhenItIsRead) {
  const CsvTable t = parse_csv("a,b,a\n1,2,3\n", "f.csv");
  EXPECT_EQ(t.column("b"), 1);
  try {
    t.column("a");
    FAIL() << "no error for a duplicate column";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("duplicate column 'a' (columns 1 and 3)"),
              std::string::npos)
        << e.what();
  }
}

TEST(Csv, TinyAndHugeNumbers) {
  const CsvTable t = parse_csv("a\n1e-320\n-1e308\n0x1p-3\n", "f.csv");
  EXPECT_GT(*t.number(t.rows[0], 0), 0.0);  // subnormal, not an error
  EXPECT_EQ(*t.number(t.rows[1], 0), -1e308);
  EXPECT_EQ(*t.number(t.rows[2], 0), 0.125);
}

TEST(Csv, SuggestsTheClosestColumn) {
  const CsvTable t = parse_csv("VX_mps,omega_rpm,Fx_n,zzz\n", "f.csv");
  EXPECT_EQ(t.closest_column("vx_mps"), "VX_mps");
  EXPECT_EQ(t.closest_column("omega_radps"), "omega_rpm");  // same quantity, other unit
  EXPECT_EQ(t.closest_column("Fx_N"), "Fx_n");
  EXPECT_EQ(t.closest_column("Mz_Nm"), "");
  // The table's suggestion is closest_name over its header (the measured-data reader's checks
  // call closest_name on the header cells directly).
  EXPECT_EQ(closest_name(t.header, "omega_radps"), "omega_rpm");
  EXPECT_EQ(closest_name(t.header, "omega_radps", {"omega_rpm"}), "");  // excluded
  EXPECT_EQ(closest_name({}, "Fx_N"), "");
}

TEST(Csv, MissingFileIsAnError) {
  EXPECT_THROW(read_csv("/nonexistent/file.csv"), ParseError);
}

// The cells of a row in one block: read back as written, copied deeply, grown a cell at a time,
// and no larger than their text plus 4 bytes a cell (and 4 for the count).
TEST(Csv, RowCellsTakeTheirTextPlusFourBytesACell) {
  CsvCells cells(std::vector<std::string>{"1.5", "", "said \"hi\"", "-2e3"});
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_EQ(cells[0], "1.5");
  EXPECT_EQ(cells[1], "");
  EXPECT_EQ(cells.view(2), "said \"hi\"");
  EXPECT_EQ(cells.heap_bytes(), 3u + 0u + 9u + 4u + 4u * 5u);
  CsvCells copy = cells;
  copy.push_back("x");
  EXPECT_EQ(cells.size(), 4u);
  EXPECT_EQ(copy.size(), 5u);
  EXPECT_EQ(copy.strings(), (std::vector<std::string>{"1.5", "", "said \"hi\"", "-2e3", "x"}));
  EXPECT_THROW(cells.view(4), std::out_of_range);
  EXPECT_EQ(CsvCells().size(), 0u);
  EXPECT_EQ(CsvCells().heap_bytes(), 0u);
  // A table's rows as parse_csv builds them.
  const CsvTable t = parse_csv("a,b,c\n1,22,333\n", "mem.csv");
  EXPECT_EQ(t.rows[0].cells.heap_bytes(), 6u + 4u * 4u);
}

// Each bound of CsvLimits ends the read with an error naming it, at the line where it is passed.
TEST(Csv, ReadingStopsAtEachStatedBound) {
  CsvLimits l;
  l.max_line_bytes = 16;
  try {
    parse_csv("a,b\n1,2\n123456789,123456789\n", "f.csv", l);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_NE(std::string(e.what()).find("a line longer than 16 bytes"), std::string::npos);
  }
  EXPECT_NO_THROW(parse_csv("a,b\n1234567,12345678\n", "f.csv", l));  // 16 bytes: the limit
  l = CsvLimits{};
  l.max_rows = 2;
  EXPECT_EQ(parse_csv("a\n1\n# two rows\n2\n", "f.csv", l).rows.size(), 2u);
  try {
    parse_csv("a\n1\n2\n3\n", "f.csv", l);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 4) << e.what();
    EXPECT_NE(
        std::string(e.what()).find("3 rows of data or more: past the reader's limit of 2 rows"),
        std::string::npos);
  }
  l = CsvLimits{};
  l.max_lines = 3;
  try {
    parse_csv("a\n#\n\n\n1\n", "f.csv", l);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 4) << e.what();
    EXPECT_NE(std::string(e.what()).find("more than 3 lines"), std::string::npos);
  }
  l = CsvLimits{};
  l.max_memory_bytes = 1000;  // a row of "1" takes its CsvRow, 9 bytes and the allocator's 16
  std::string many = "a\n";
  for (int i = 0; i < 100; ++i) many += "1\n";
  try {
    parse_csv(many, "f.csv", l);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("the table takes more than 1000 bytes of memory after"),
              std::string::npos)
        << e.what();
  }
  l = CsvLimits{};
  l.max_input_bytes = 10;
  EXPECT_THROW(parse_csv("a\n1\n2\n3\n4\n5\n", "f.csv", l), ParseError);
  EXPECT_NO_THROW(parse_csv("a\n1\n2\n3\n4\n", "f.csv", l));  // 10 bytes
}

// The reader checks as it reads, a block at a time: an endless device ends at once with the
// byte's position, and lines (CRLF included) cut across the 64 KiB blocks read back whole.
TEST(Csv, ReadsAsItGoesAndChecksEachByte) {
  try {
    read_csv("/dev/zero");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.column(), 1);
    EXPECT_NE(std::string(e.what()).find("a NUL byte"), std::string::npos);
  }
  const std::string path = contensou::test::temp_path("contensou-csv-blocks.csv");
  std::string text = "x,y\r\n";
  int rows = 0;
  while (text.size() < 3 * 65536) {
    text += std::to_string(rows) + "," + std::to_string(2 * rows) + (rows % 3 ? "\r\n" : "\n");
    ++rows;
  }
  bool crlf_cut = false;  // some shift puts a CRLF's CR last in a block, its LF first in the next
  for (std::size_t shift = 0; shift < 40; ++shift) {
    const std::string shifted = std::string(shift, '#') + "\n" + text;
    crlf_cut = crlf_cut || (shifted[65535] == '\r' && shifted[65536] == '\n');
    {
      std::ofstream out(path, std::ios::binary);
      out << shifted;
    }
    const CsvTable t = read_csv(path);
    ASSERT_EQ(t.rows.size(), static_cast<std::size_t>(rows));
    for (int r : {0, rows / 2, rows - 1})
      EXPECT_EQ(*t.number(t.rows[static_cast<std::size_t>(r)], 1), 2.0 * r);
    EXPECT_EQ(t.rows.back().line, rows + 2);
  }
  EXPECT_TRUE(crlf_cut);
  std::remove(path.c_str());
}
