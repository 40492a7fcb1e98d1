#include <gtest/gtest.h>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"

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
