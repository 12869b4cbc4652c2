#include "evaluator/core/text_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <array>
#include <fstream>

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

TEST(TextFileTest, NumberFieldsTakeExactlyTheCountOfFiniteNumbers) {
  std::array<double, 3> values{};
  ASSERT_TRUE(ParseNumberFields(" 1.5\t-2e3  0x\r", values) == false);  // "0x" is not a number
  ASSERT_TRUE(ParseNumberFields(" 1.5\t-2e3  7\r", values));
  EXPECT_EQ(values, (std::array<double, 3>{1.5, -2000.0, 7.0}));
  EXPECT_FALSE(ParseNumberFields("1 2", values));
  EXPECT_FALSE(ParseNumberFields("1 2 3 4", values));
  EXPECT_FALSE(ParseNumberFields("1 nan 3", values));
  EXPECT_FALSE(ParseNumberFields("1 2 1e999", values));
  EXPECT_FALSE(ParseNumberFields("1,2,3", values));
}

TEST(TextFileTest, CountLinesCountsALastLineWithoutNewline) {
  EXPECT_EQ(CountLines(""), 0u);
  EXPECT_EQ(CountLines("a"), 1u);
  EXPECT_EQ(CountLines("a\n"), 1u);
  EXPECT_EQ(CountLines("a\n\nb"), 3u);
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
