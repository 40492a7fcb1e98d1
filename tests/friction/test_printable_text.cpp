// The check of names written into structured outputs (printable_text.hpp): control characters
// and broken UTF-8 are found at their byte and refused by name; tabs, newlines and well-formed
// multi-byte characters pass.
#include <gtest/gtest.h>

#include <string>

#include "contensou/friction/error.hpp"
#include "contensou/friction/printable_text.hpp"

using namespace contensou;

TEST(PrintableText, FindsControlCharactersAndBrokenUtf8AtTheirByte) {
  std::string what;
  EXPECT_EQ(first_unprintable("tire model 2\t(front)\n", &what), std::string::npos);
  EXPECT_EQ(first_unprintable("Reifen \xc3\xa4 \xe2\x82\xac \xf0\x9f\x9b\x9e"), std::string::npos);
  EXPECT_EQ(first_unprintable(std::string("a\x01"
                                          "b\x1b"
                                          "c"),
                              &what),
            1u);
  EXPECT_EQ(what, "the control character U+0001");
  EXPECT_EQ(first_unprintable("tire\abell", &what), 4u);
  EXPECT_EQ(what, "the control character U+0007");
  EXPECT_EQ(first_unprintable(std::string("x\0y", 3)), 1u);
  EXPECT_EQ(first_unprintable("del\x7f"), 3u);
  EXPECT_EQ(first_unprintable("ab\xc3", &what), 2u);  // a lead byte cut off
  EXPECT_EQ(what, "a byte that is not UTF-8");
  EXPECT_EQ(first_unprintable("a\x80"), 1u);         // a continuation byte alone
  EXPECT_EQ(first_unprintable("\xc0\xaf"), 0u);      // an overlong '/'
  EXPECT_EQ(first_unprintable("\xe2\x28\xa1"), 0u);  // a bad continuation
}

TEST(PrintableText, RefusesNamingTheParameterTheByteAndTheCharacter) {
  EXPECT_NO_THROW(require_printable("model_name", "contensou_law"));
  try {
    require_printable("model_name", std::string("a\x01"
                                                "b"));
    ADD_FAILURE() << "a control character passed";
  } catch (const InvalidArgument& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.parameter(), "model_name");
    EXPECT_NE(m.find("\"a\\x01b\""), std::string::npos) << m;
    EXPECT_NE(m.find("byte 2 is the control character U+0001"), std::string::npos) << m;
  }
}
