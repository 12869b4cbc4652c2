// Well-formed UTF-8 (RFC 3629), as JSON output requires it of every string.
#include "evaluator/core/utf8_text.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

TEST(Utf8TextTest, WellFormedTextPasses) {
  EXPECT_EQ(FirstInvalidUtf8(""), std::nullopt);
  EXPECT_EQ(FirstInvalidUtf8("plain ASCII\n"), std::nullopt);
  // 2, 3 and 4 bytes, the byte order mark, the largest code point and the last before the surrogates.
  EXPECT_EQ(FirstInvalidUtf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x97\xBA \xEF\xBB\xBF \xF4\x8F\xBF\xBF \xED\x9F\xBF"),
            std::nullopt);
}

TEST(Utf8TextTest, TheFirstByteThatIsNotUtf8IsFound) {
  EXPECT_EQ(FirstInvalidUtf8("ab\xFE"), 2u);                // never in UTF-8
  EXPECT_EQ(FirstInvalidUtf8("a\x80"), 1u);                 // a continuation byte alone
  EXPECT_EQ(FirstInvalidUtf8("\xC0\x80"), 0u);              // overlong NUL
  EXPECT_EQ(FirstInvalidUtf8("x\xE0\x80\xAF"), 1u);         // overlong '/'
  EXPECT_EQ(FirstInvalidUtf8("\xED\xA0\x80"), 0u);          // a surrogate
  EXPECT_EQ(FirstInvalidUtf8("\xF4\x90\x80\x80"), 0u);      // beyond U+10FFFF
  EXPECT_EQ(FirstInvalidUtf8("ok \xE2\x82"), 3u);           // cut short
  EXPECT_EQ(FirstInvalidUtf8("\xC3\xA9\xE2\x28\xA1"), 2u);  // a continuation that is not one
}

TEST(Utf8TextTest, RequireUtf8NamesFileLineAndColumn) {
  try {
    RequireUtf8("a: 1\nb: x\xFFy\n", "/data/sweep.yaml", "a sweep file is UTF-8");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "/data/sweep.yaml:2:5: not UTF-8 text (byte 0xFF): a sweep file is UTF-8");
  }
  EXPECT_NO_THROW(RequireUtf8("a: caf\xC3\xA9\tb\r\n", "/data/sweep.yaml", "a sweep file is UTF-8"));
}

TEST(Utf8TextTest, RequireUtf8RefusesControlCharactersYamlDoesNotAllow) {
  for (const std::string& text : {std::string("a: \0N\n", 6), std::string("a: \x08\n"), std::string("a: \x7F\n")}) {
    try {
      RequireUtf8(text, "/data/sweep.yaml", "a sweep file is UTF-8");
      FAIL() << "expected an InputError";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), ::testing::HasSubstr("/data/sweep.yaml:1:4: a control character (byte 0x"));
    }
  }
}

}  // namespace
}  // namespace slamsweep::evaluator
