#include "evaluator/core/text_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

std::string WriteGzip(const std::filesystem::path& path, const std::string& content) {
  gzFile file = gzopen(path.c_str(), "wb");
  gzwrite(file, content.data(), static_cast<unsigned>(content.size()));
  gzclose(file);
  return path.string();
}

TEST(TextFileTest, ReadsPlainAndGzipTheSame) {
  testing::TempDir dir;
  const std::string content = "a b c\n1 2 3\n";
  testing::WriteFile(dir / "plain.txt", content);
  WriteGzip(dir / "packed.txt.gz", content);
  EXPECT_EQ(ReadTextFile(dir / "plain.txt"), content);
  EXPECT_EQ(ReadTextFile(dir / "packed.txt.gz"), content);
}

TEST(TextFileTest, TruncatedGzipNamesTheFile) {
  testing::TempDir dir;
  std::string content;
  for (int i = 0; i < 20000; ++i) content += "FLASER " + std::to_string(i) + " 1 2 3\n";
  WriteGzip(dir / "full.gz", content);
  const std::string packed = ReadTextFile(dir / "full.gz");
  ASSERT_EQ(packed, content);
  // Cut the compressed file in half.
  std::ifstream in(dir / "full.gz", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  testing::WriteFile(dir / "cut.gz", bytes.substr(0, bytes.size() / 2));
  try {
    ReadTextFile(dir / "cut.gz");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("cut.gz"));
    EXPECT_THAT(error.what(), HasSubstr("truncated"));
  }
}

TEST(TextFileTest, PlainFilesAreReadInPlaceAndProcFilesToo) {
  testing::TempDir dir;
  testing::WriteFile(dir / "plain.txt", "1 2\n3 4\n");
  EXPECT_EQ(ReadTextFileContent(dir / "plain.txt").text(), "1 2\n3 4\n");
  testing::WriteFile(dir / "empty.txt", "");
  EXPECT_EQ(ReadTextFileContent(dir / "empty.txt").text(), "");
  // /proc files say they hold 0 bytes; their content is read, not mapped.
  EXPECT_THAT(std::string(ReadTextFileContent("/proc/self/status").text()), HasSubstr("Name:"));
}

TEST(TextFileTest, NumberLinesTakeExactlyTheCountOfFiniteNumbersAndPassOnTheRest) {
  const std::string content =
      "# header\n"
      " 1.5\t-2e3  7\r\n"  // numbers, any blanks
      "\n"
      "  # indented comment\n"
      "1 2 0x\n"   // not a number
      "1 2\n"      // too few
      "1 2 3 4\n"  // too many
      "1 nan 3\n"  // not finite
      "1 2-3 4\n"  // fields must be separated by blanks
      "4 5 6";     // last line without a newline
  std::vector<std::pair<std::size_t, std::array<double, 3>>> numbers;
  std::vector<std::pair<std::size_t, std::string>> others;
  ForEachNumberLine<3>(
      content,
      [&](const std::array<double, 3>& values, std::string_view line, std::size_t line_number) {
        numbers.emplace_back(line_number, values);
        EXPECT_EQ(SplitFields(line, " \t\r").size(), 3u) << line;
      },
      [&](std::string_view line, std::size_t line_number) { others.emplace_back(line_number, std::string(line)); });
  ASSERT_EQ(numbers.size(), 2u);
  EXPECT_EQ(numbers[0], (std::pair<std::size_t, std::array<double, 3>>{2, {1.5, -2000.0, 7.0}}));
  EXPECT_EQ(numbers[1], (std::pair<std::size_t, std::array<double, 3>>{10, {4.0, 5.0, 6.0}}));
  const std::vector<std::pair<std::size_t, std::string>> expected_others = {
      {5, "1 2 0x"}, {6, "1 2"}, {7, "1 2 3 4"}, {8, "1 nan 3"}, {9, "1 2-3 4"}};
  EXPECT_EQ(others, expected_others);
}

TEST(TextFileTest, QuickNumberReaderAgreesWithFromChars) {
  // TextRecord::Number's rule (std::from_chars, finite only) is the specification.
  std::vector<std::string> tokens = {"0",
                                     "-0",
                                     "0.000",
                                     "0e-999",
                                     "00012",
                                     ".5",
                                     "5.",
                                     "-.5e3",
                                     "1e",
                                     "1e+",
                                     "1E-3",
                                     "1e-320",
                                     "4.9406564584124654e-324",
                                     "1e-400",
                                     "-1e-400",
                                     "1e308",
                                     "1e309",
                                     "-1e400",
                                     "inf",
                                     "nan",
                                     "+1",
                                     "--1",
                                     "0x1p3",
                                     "1.5x",
                                     "123456789012345678901234567890",
                                     "0.1000000000000000055511151231257827",
                                     "2.2250738585072011e-308",
                                     "e5",
                                     "-",
                                     ""};
  std::mt19937_64 random(3);
  for (int i = 0; i < 2000; ++i) {
    const double x = std::ldexp(std::uniform_real_distribution<double>(-1.0, 1.0)(random),
                                std::uniform_int_distribution<int>(-1070, 1020)(random));
    std::array<char, 40> buffer{};
    tokens.emplace_back(buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), x).ptr);
  }
  for (const std::string& token : tokens) {
    const char* first = token.data();
    const char* last = token.data() + token.size();
    double expected = 0.0;
    const auto [expected_stop, error] = std::from_chars(first, last, expected);
    const bool accepted = error == std::errc() && std::isfinite(expected);
    double actual = 0.0;
    const char* stop = ReadFiniteNumber(first, last, actual);
    ASSERT_EQ(stop != nullptr, accepted) << "'" << token << "'";
    if (!accepted) continue;
    EXPECT_EQ(stop, expected_stop) << "'" << token << "'";
    EXPECT_EQ(std::bit_cast<std::uint64_t>(actual), std::bit_cast<std::uint64_t>(expected)) << "'" << token << "'";
  }
}

TEST(TextFileTest, CountLinesCountsEveryLineWithOrWithoutItsLastNewline) {
  EXPECT_EQ(CountLines(""), 0u);
  EXPECT_EQ(CountLines("\n"), 1u);
  EXPECT_EQ(CountLines("a"), 1u);
  EXPECT_EQ(CountLines("a\nb"), 2u);
  EXPECT_EQ(CountLines("# comment\n\n0 1 2\n"), 3u);
  std::string content;
  for (int i = 0; i < 1000; ++i) content += i % 7 == 0 ? "0.123456789 0.2 0.3\n" : "1 2 3\n";
  EXPECT_EQ(CountLines(content), 1000u);
}

TEST(TextFileTest, MissingFileIsAnInputError) {
  EXPECT_THROW(ReadTextFile("/nonexistent/slamsweep/file.txt"), InputError);
}

TEST(TextFileTest, RecordsSkipCommentsAndBlankLinesButKeepLineNumbers) {
  const std::filesystem::path file = "mem.txt";
  std::vector<std::size_t> lines;
  std::vector<std::size_t> counts;
  ForEachRecord(file, "# header\n\n1 2\n  # indented comment\n3 4 5\n", [&](const TextRecord& record) {
    lines.push_back(record.line_number());
    counts.push_back(record.size());
  });
  EXPECT_EQ(lines, (std::vector<std::size_t>{3, 5}));
  EXPECT_EQ(counts, (std::vector<std::size_t>{2, 3}));
}

TEST(TextFileTest, NonNumericFieldNamesFileLineAndField) {
  const std::filesystem::path file = "poses.txt";
  try {
    ForEachRecord(file, "1 2\n3 abc\n", [&](const TextRecord& record) { record.Number(1, "y"); });
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("poses.txt:2"));
    EXPECT_THAT(error.what(), HasSubstr("field 2 (y)"));
    EXPECT_THAT(error.what(), HasSubstr("'abc'"));
  }
}

TEST(TextFileTest, NanIsNotAFiniteNumber) {
  const std::filesystem::path file = "f";
  EXPECT_THROW(ForEachRecord(file, "nan\n", [](const TextRecord& r) { r.Number(0, "x"); }), InputError);
  EXPECT_THROW(ForEachRecord(file, "1e999\n", [](const TextRecord& r) { r.Number(0, "x"); }), InputError);
}

TEST(TextFileTest, CommaSeparatedFieldsAreTrimmed) {
  const auto fields = SplitFields("1, 2 ,3,", ",");
  ASSERT_EQ(fields.size(), 4u);
  EXPECT_EQ(fields[0], "1");
  EXPECT_EQ(fields[1], "2");
  EXPECT_EQ(fields[2], "3");
  EXPECT_EQ(fields[3], "");
}

}  // namespace
}  // namespace slamsweep::evaluator
