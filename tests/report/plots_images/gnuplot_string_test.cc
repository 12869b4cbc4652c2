#include "report/plots/gnuplot_string.h"

#include <gtest/gtest.h>

namespace slamsweep::report {
namespace {

TEST(GnuplotQuotedTest, WrapsPlainTextInSingleQuotes) { EXPECT_EQ(GnuplotQuoted("ATE rmse"), "'ATE rmse'"); }

TEST(GnuplotQuotedTest, JoinsSingleQuotesInAsCharacterCodes) {
  EXPECT_EQ(GnuplotQuoted("it's"), "'it' . sprintf('%c', 39) . 's'");
  EXPECT_EQ(GnuplotQuoted("''"), "'' . sprintf('%c', 39) . '' . sprintf('%c', 39) . ''");
}

TEST(GnuplotQuotedTest, KeepsBackslashesBackquotesAndMarkupLiterally) {
  // Inside single quotes gnuplot expands none of these, so they pass through unchanged.
  EXPECT_EQ(GnuplotQuoted(R"(a\b `cmd` @m "x" <script>)"), R"('a\b `cmd` @m "x" <script>')");
}

TEST(GnuplotQuotedTest, ReplacesControlCharactersThatWouldEndTheCommand) {
  EXPECT_EQ(GnuplotQuoted("a\nb\tc\rd"), "'a b c d'");
}

TEST(GnuplotQuotedTest, EmptyText) { EXPECT_EQ(GnuplotQuoted(""), "''"); }

}  // namespace
}  // namespace slamsweep::report
