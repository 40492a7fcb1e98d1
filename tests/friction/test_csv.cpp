#include <gtest/gtest.h>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"

using namespace contensou;

TEST(Csv, ParsesCommentsEmptyCellsAndAnyColumnOrder) {
  const CsvTable t = parse_csv("# comment\nb, a\n 1.5 ,\n#x\n-2,3e2\n", "mem.csv");
  ASSERT_EQ(t.header.size(), 2u);
  EXPECT_EQ(t.column("a"), 1);
  EXPECT_EQ(t.column("b"), 0);
  EXPECT_EQ(t.column("c"), -1);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].line, 3);
  EXPECT_DOUBLE_EQ(*t.rows[0].cells[0], 1.5);
  EXPECT_FALSE(t.rows[0].cells[1].has_value());
  EXPECT_DOUBLE_EQ(*t.rows[1].cells[1], 300.0);
}

void expect_parse_error(const std::string& text, int line, int column, const std::string& part) {
  try {
    parse_csv(text, "f.csv");
    FAIL() << "no error for: " << text;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("f.csv"), std::string::npos) << e.what();
  }
}

TEST(Csv, NamesLineAndColumnOfBadCells) {
  expect_parse_error("a,b\n1,x2\n", 2, 3, "not a number");
  expect_parse_error("a,b\n1,2\n1,nan\n", 3, 3, "non-finite");
  expect_parse_error("a,b\n1,2,3\n", 2, 5, "expected 2 cells");
  expect_parse_error("a,a\n", 1, 3, "duplicate");
  expect_parse_error("# only a comment\n", 1, 1, "no header");
  expect_parse_error("a,b\n1,1e999\n", 2, 3, "not a number");
}

TEST(Csv, MissingFileIsAnError) {
  EXPECT_THROW(read_csv("/nonexistent/file.csv"), ParseError);
}
