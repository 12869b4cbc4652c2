#include "evaluator/core/gzip_inflate.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>

namespace slamsweep::evaluator {
namespace {

// One gzip member of `content`, written by zlib (the independent implementation).
std::string GzipMember(const std::string& content) {
  z_stream stream{};
  EXPECT_EQ(deflateInit2(&stream, Z_BEST_SPEED, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&stream, static_cast<uLong>(content.size())) + 64, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(content.data()));
  stream.avail_in = static_cast<uInt>(content.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return out;
}

std::string Lines(int count, const std::string& word) {
  std::string text;
  for (int i = 0; i < count; ++i) text += word + " " + std::to_string(i * 7919 % 10007) + "\n";
  return text;
}

TEST(GzipInflateTest, InflatesOneMember) {
  const std::string content = Lines(50000, "FLASER");
  EXPECT_EQ(InflateWholeGzip(GzipMember(content)), content);
  EXPECT_EQ(InflateWholeGzip(GzipMember("")), std::string());
}

TEST(GzipInflateTest, ConcatenatedMembersAreReadInOrderAndTrailingBytesIgnored) {
  // The last member is tiny, so its size field understates the whole: the buffer has to grow.
  const std::string first = Lines(40000, "ODOM");
  const std::string second = "PARAM robot_front_laser_max 80\n";
  const std::string data = GzipMember(first) + GzipMember(second);
  EXPECT_EQ(InflateWholeGzip(data), first + second);
  EXPECT_EQ(InflateWholeGzip(data + std::string(100, '\0')), first + second);  // as zlib's gzread
}

TEST(GzipInflateTest, DamagedDataGivesNothingSoThatTheCallerCanSayWhere) {
  const std::string member = GzipMember(Lines(20000, "FLASER"));
  EXPECT_EQ(InflateWholeGzip(member.substr(0, member.size() / 2)), std::nullopt);  // truncated
  std::string flipped = member;
  flipped[flipped.size() - 6] = static_cast<char>(flipped[flipped.size() - 6] ^ 0x55);  // CRC mismatch
  EXPECT_EQ(InflateWholeGzip(flipped), std::nullopt);
  EXPECT_EQ(InflateWholeGzip("plain text\n"), std::nullopt);
  EXPECT_EQ(InflateWholeGzip(""), std::nullopt);
  EXPECT_TRUE(HasGzipMagic(member));
  EXPECT_FALSE(HasGzipMagic("\x1f"));
}

TEST(GzipInflateTest, TheCapIsAHundredTimesTheFileAndAtLeast16MiB) {
  EXPECT_EQ(GzipInflateCap(0), std::size_t{16} << 20);
  EXPECT_EQ(GzipInflateCap(1000), std::size_t{16} << 20);
  EXPECT_EQ(GzipInflateCap(std::size_t{1} << 20), std::size_t{100} << 20);
  EXPECT_EQ(GzipInflateCap(SIZE_MAX), SIZE_MAX);
  EXPECT_EQ(GzipInflateCapMessage(2048),
            "gzip data inflates to more than 16.0 MiB, the cap for a file of 2.0 KiB (100 times its size, at least "
            "16.0 MiB)");
}

TEST(GzipInflateTest, DataBeyondTheCapGivesNothing) {
  // 17 MiB of one byte compress to about 17 KiB: the cap is 16 MiB.
  const std::string content(std::size_t{17} << 20, 'x');
  const std::string member = GzipMember(content);
  ASSERT_LT(member.size() * 100, std::size_t{16} << 20);
  EXPECT_EQ(InflateWholeGzip(member), std::nullopt);
  // Just under the cap is read.
  const std::string under(std::size_t{16} << 20, 'x');
  EXPECT_EQ(InflateWholeGzip(GzipMember(under)), under);
}

TEST(GzipInflateTest, ASizeFieldClaimingGigabytesIsNotBelieved) {
  // ISIZE says 4 GiB - 1 for a member of a few bytes: the data is damaged (the size does not match) and is
  // refused without a buffer of the claimed size.
  std::string member = GzipMember("FLASER 3 1 2 3\n");
  member.replace(member.size() - 4, 4, "\xff\xff\xff\xff");
  EXPECT_EQ(InflateWholeGzip(member), std::nullopt);
}

}  // namespace
}  // namespace slamsweep::evaluator
