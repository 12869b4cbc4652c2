#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "report/html/html.h"
#include "report/html/number_format.h"
#include "report/html/safe_name.h"

namespace slamsweep::report {
namespace {

TEST(EscapeHtmlTest, EscapesEveryMarkupCharacter) {
  EXPECT_EQ(EscapeHtml(R"(<a href="x" title='y'>&</a>)"),
            "&lt;a href=&quot;x&quot; title=&#39;y&#39;&gt;&amp;&lt;/a&gt;");
  EXPECT_EQ(EscapeHtml("plain ▼ text"), "plain ▼ text");
}

TEST(HtmlTest, ElementEscapesTextButKeepsTrustedMarkup) {
  EXPECT_EQ(Element("td", "best", Html::Escape("<b>")).str(), "<td class=\"best\">&lt;b&gt;</td>");
  EXPECT_EQ(Link("runs/a&b.html", Html::Escape("x")).str(), "<a href=\"runs/a&amp;b.html\">x</a>");
}

TEST(RenderTemplateTest, FillsPlaceholders) {
  EXPECT_EQ(
      RenderTemplate("<p>{{a}} and {{b}}</p>", {{"a", Html::Escape("1<2")}, {"b", Html::Trusted("<i>x</i>")}}).str(),
      "<p>1&lt;2 and <i>x</i></p>");
}

TEST(RenderTemplateTest, MissingOrUnusedFieldIsAProgrammingError) {
  EXPECT_THROW(RenderTemplate("{{a}}", {}), std::logic_error);
  EXPECT_THROW(RenderTemplate("x", {{"a", Html()}}), std::logic_error);
  EXPECT_THROW(RenderTemplate("{{a", {{"a", Html()}}), std::logic_error);
}

TEST(SafeFileNameTest, KeepsSafeNamesAndHashesChangedOnes) {
  EXPECT_EQ(SafeFileName("icp-slam-intel-clean-i0-1a2b3c4d"), "icp-slam-intel-clean-i0-1a2b3c4d");
  const std::string hostile = SafeFileName("../../etc/passwd");
  EXPECT_EQ(hostile.find('/'), std::string::npos);
  EXPECT_NE(hostile.front(), '.');
  EXPECT_NE(SafeFileName("a/b"), SafeFileName("a_b"));
  EXPECT_NE(SafeFileName(""), "");
  EXPECT_NE(SafeFileName(".."), "..");
  EXPECT_NE(SafeFileName("."), ".");
  const std::string long_name(300, 'x');
  EXPECT_LE(SafeFileName(long_name).size(), 64u);
  EXPECT_NE(SafeFileName(long_name), SafeFileName(long_name + "y"));
  for (char c : SafeFileName("<script>alert(1)</script>")) {
    EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.') << c;
  }
}

TEST(NumberFormatTest, SignificantDigitsWithoutExponent) {
  EXPECT_EQ(FormatNumber(0.123456), "0.1235");
  EXPECT_EQ(FormatNumber(12.3456), "12.35");
  EXPECT_EQ(FormatNumber(1234.56), "1235");
  EXPECT_EQ(FormatNumber(0.000123456), "0.0001235");
  EXPECT_EQ(FormatNumber(42.0), "42");
  EXPECT_EQ(FormatNumber(-0.5), "-0.5000");
  EXPECT_EQ(FormatNumber(std::nan("")), "n/a");
}

TEST(NumberFormatTest, MeanStd) {
  MeanStd three;
  three.n = 3;
  three.mean = 0.11;
  three.std = 0.01;
  EXPECT_EQ(FormatMeanStd(three), "0.1100 ± 0.0100");
  MeanStd one;
  one.n = 1;
  one.mean = 0.5;
  EXPECT_EQ(FormatMeanStd(one), "0.5000 ± n/a");
  MeanStd counts;
  counts.n = 3;
  counts.mean = 13.0;
  counts.std = 2.13;
  EXPECT_EQ(FormatMeanStd(counts), "13.0 ± 2.1");
  counts.std = 1.0;
  EXPECT_EQ(FormatMeanStd(counts), "13 ± 1");
  EXPECT_EQ(FormatMeanStd({}), "n/a");
}

}  // namespace
}  // namespace slamsweep::report
