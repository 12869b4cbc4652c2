// SHA-256 digests through libcrypto loaded on first use: the values are the published test vectors of
// FIPS 180-2 (appendix B.1) and of the empty message.
#include "orchestrator/build_identity/file_digest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator {
namespace {

constexpr const char* kAbc = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
constexpr const char* kEmpty = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";

TEST(FileDigestTest, BytesGiveThePublishedDigests) {
  EXPECT_EQ(Sha256OfBytes("abc"), kAbc);
  EXPECT_EQ(Sha256OfBytes(""), kEmpty);
}

TEST(FileDigestTest, AFileGivesTheDigestOfItsBytes) {
  const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "file_digest_abc.bin";
  std::ofstream(file, std::ios::binary) << "abc";
  EXPECT_EQ(Sha256OfFile(file), kAbc);
  // Longer than one read buffer (64 KiB): the digest runs over every chunk.
  const std::string large(200'000, 'x');
  std::ofstream(file, std::ios::binary | std::ios::trunc) << large;
  EXPECT_EQ(Sha256OfFile(file), Sha256OfBytes(large));
  std::filesystem::remove(file);
}

TEST(FileDigestTest, AMissingFileIsNamed) {
  try {
    Sha256OfFile("/nonexistent/slamsweep-digest-input");
    FAIL() << "no error";
  } catch (const evaluator::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/slamsweep-digest-input"), std::string::npos);
  }
}

}  // namespace
}  // namespace slamsweep::orchestrator
