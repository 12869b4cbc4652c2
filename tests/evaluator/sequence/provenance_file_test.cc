#include "evaluator/sequence/provenance_file.h"

#include <gtest/gtest.h>

#include "tests/support/shared_data.h"

namespace slamsweep::evaluator {
namespace {

constexpr const char* kText =
    "Dataset: demo\n"
    "\n"
    "File: demo.log.gz  (sha256 abc)\n"
    "Stats: demo.log.gz: FLASER=3\n"
    "\n"
    "Source repository : https://example.org/repo  (MIT)\n"
    "Commit (snapshot) : 0123abcd   (file added later)\n"
    "Repo path         : data/demo.log.gz\n"
    "Original provenance: An archive / the authors\n"
    "  (second line of it).\n"
    "License note       : Free for research,\n"
    "  cite the authors.\n"
    "Format             : CARMEN\n"
    "  FLASER n ...\n"
    "\n"
    "File: demo.relations\n"
    "Original provenance: Relations by someone else\n";

TEST(ProvenanceFileTest, ReadsTheBlockOfTheNamedFile) {
  const std::optional<Provenance> provenance = ParseProvenanceText(kText, "demo.log.gz");
  ASSERT_TRUE(provenance.has_value());
  EXPECT_EQ(provenance->source, "https://example.org/repo (MIT); commit 0123abcd; path data/demo.log.gz");
  EXPECT_EQ(provenance->citation, "An archive / the authors (second line of it).");
  EXPECT_EQ(provenance->licence_note, "Free for research, cite the authors.");

  const std::optional<Provenance> relations = ParseProvenanceText(kText, "demo.relations");
  ASSERT_TRUE(relations.has_value());
  EXPECT_EQ(relations->citation, "Relations by someone else");
  EXPECT_EQ(relations->source, "");
}

TEST(ProvenanceFileTest, UnknownFileHasNoProvenance) {
  EXPECT_FALSE(ParseProvenanceText(kText, "other.log").has_value());
  EXPECT_FALSE(ParseProvenanceText("", "demo.log.gz").has_value());
}

TEST(ProvenanceFileTest, MissingProvenanceFileIsNotAnError) {
  const testing::TempDir dir;
  EXPECT_FALSE(ReadProvenanceBeside(testing::WriteFile(dir / "x.log", "FLASER")).has_value());
}

TEST(ProvenanceFileTest, ReadsTheSharedIntelProvenance) {
  SLAMSWEEP_REQUIRE_SHARED(log, "datasets/intel/intel-corrected.log.gz");
  const std::optional<Provenance> provenance = ReadProvenanceBeside(log);
  ASSERT_TRUE(provenance.has_value());
  EXPECT_NE(provenance->source.find("github.com/acschaefer/ple"), std::string::npos) << provenance->source;
  EXPECT_NE(provenance->source.find("data/carmen/intel-corrected.log.gz"), std::string::npos) << provenance->source;
  EXPECT_NE(provenance->citation.find("Radish"), std::string::npos) << provenance->citation;
  EXPECT_NE(provenance->licence_note.find("citation of the original authors"), std::string::npos)
      << provenance->licence_note;
}

}  // namespace
}  // namespace slamsweep::evaluator
