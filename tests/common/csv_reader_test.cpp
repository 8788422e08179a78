// Tests of the CSV reader: splitting and quoting, blank lines, CRLF, line numbers, broken quotes.
#include "common/csv_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "input_error_message.h"

namespace echoplan {
namespace {

using Fields = std::vector<std::string>;

TEST(SplitCsvLine, PlainQuotedAndEmptyFields) {
  Fields f;
  ASSERT_TRUE(split_csv_line("a,b,", f));
  EXPECT_EQ(f, (Fields{"a", "b", ""}));
  ASSERT_TRUE(split_csv_line(R"("x,y","say ""hi""",3)", f));
  EXPECT_EQ(f, (Fields{"x,y", R"(say "hi")", "3"}));
  ASSERT_TRUE(split_csv_line("", f));
  EXPECT_EQ(f, (Fields{""}));
  EXPECT_FALSE(split_csv_line(R"(a,"b)", f));
}

TEST(CsvReader, RowsWithTheirLinesSkippingBlankLinesAndCarriageReturns) {
  CsvReader reader("h1,h2\r\n\r\n1,2\n\n3,4", "t.csv");
  Fields f;
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f, (Fields{"h1", "h2"}));
  EXPECT_EQ(reader.line(), 1);
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f, (Fields{"1", "2"}));
  EXPECT_EQ(reader.line(), 3);
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f, (Fields{"3", "4"}));
  EXPECT_EQ(reader.line(), 5);
  EXPECT_FALSE(reader.next(f));
  EXPECT_EQ(reader.file(), "t.csv");
}

TEST(CsvReader, UnterminatedQuoteNamesFileAndLine) {
  CsvReader reader("a\n\"b\n", "t.csv");
  Fields f;
  ASSERT_TRUE(reader.next(f));
  EXPECT_THAT(input_error_message([&] { reader.next(f); }),
              ::testing::HasSubstr("t.csv:2: unterminated quote"));
}

}  // namespace
}  // namespace echoplan
