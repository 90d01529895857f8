// The report's JSON strings: escaped, and valid UTF-8 whatever bytes a name brought (a structure
// set's name in another encoding must not make the whole report unreadable).
#include "QualityReport.h"

#include <gtest/gtest.h>

namespace slicemesh::cli
{
namespace
{

const std::string replacement = "\xEF\xBF\xBD"; // U+FFFD

TEST(ReportJson, StringsAreEscaped)
{
  EXPECT_EQ(jsonString("a\"b\\c\nd\te\x01"), "\"a\\\"b\\\\c\\nd\\te\\u0001\"");
}

TEST(ReportJson, ValidUtf8IsKeptAsItIs)
{
  const std::string text = "R\xC3\xBC" "ckenmark \xE8\x82\x9D \xF0\x9F\x98\x80 \x7F";
  EXPECT_EQ(jsonString(text), "\"" + text + "\"");
}

TEST(ReportJson, EachByteThatStartsNoValidUtf8SequenceBecomesTheReplacementCharacter)
{
  // Latin-1 as a structure set stores it: one byte for the u umlaut.
  EXPECT_EQ(jsonString("R\xFC" "ckenmark"), "\"R" + replacement + "ckenmark\"");
  // A stray continuation byte, a sequence cut short (inside and at the end), an overlong '/', a
  // surrogate, a code point beyond U+10FFFF, bytes that are never UTF-8.
  EXPECT_EQ(jsonString("a\x80" "b"), "\"a" + replacement + "b\"");
  EXPECT_EQ(jsonString("\xE8\x82" "x"), "\"" + replacement + replacement + "x\"");
  EXPECT_EQ(jsonString("x\xC3"), "\"x" + replacement + "\"");
  EXPECT_EQ(jsonString("\xC0\xAF"), "\"" + replacement + replacement + "\"");
  EXPECT_EQ(jsonString("\xED\xA0\x80"), "\"" + replacement + replacement + replacement + "\"");
  EXPECT_EQ(jsonString("\xF4\x90\x80\x80"), "\"" + replacement + replacement + replacement + replacement + "\"");
  EXPECT_EQ(jsonString("\xFE\xFF"), "\"" + replacement + replacement + "\"");
  // A quote after a broken sequence is still escaped, not swallowed into it.
  EXPECT_EQ(jsonString("\xC3\""), "\"" + replacement + "\\\"\"");
}

} // namespace
} // namespace slicemesh::cli
