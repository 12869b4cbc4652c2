// Reading in a child process under limits (contained_read.h), with the sequence handed back whole
// (sequence_codec.h): every way a contained reader can end becomes the error it should be.
#include "evaluator/sequence_io/contained_read.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/sequence_codec.h"

namespace slamsweep::evaluator {
namespace {

using ::testing::HasSubstr;

Sequence EveryFieldSet() {
  Sequence sequence;
  sequence.name = "every field";
  LaserScan scan;
  scan.stamp_s = 1.5;
  scan.ranges_m = {1.0f, 2.5f, 80.0f};
  scan.angle_min_rad = -1.0;
  scan.angle_increment_rad = 0.01;
  scan.range_min_m = 0.1;
  scan.range_max_m = 80.0;
  scan.sensor_pose_on_robot = Pose::Planar(0.1, -0.2, 3.0);
  sequence.scans = {scan, scan};
  sequence.scans[1].stamp_s = 2.5;
  sequence.odometry.Add(1.5, Pose::Planar(1, 2, 0.3));
  sequence.odometry.Add(2.5, Pose::Planar(1.5, 2, 0.4));
  sequence.odometry_readings.Add(2.0, Pose::Planar(1.2, 2, 0.35));
  sequence.reference = sequence.odometry;
  sequence.relations = Relations{{1.5, 2.5, Pose::Planar(0.5, 0, 0.1)}};
  sequence.relations_outside_log = 7;
  sequence.reference_map = OccupancyGrid(3, 2, 0.1, {1.0, 2.0, 0.5}, 0.25f);
  sequence.reference_map->at(1, 2) = OccupancyGrid::kUnknown;
  sequence.provenance = {"source", "citation", "licence", "notes"};
  sequence.warnings = {"first warning", "second"};
  StampFacts facts;
  facts.outcome = StampOutcome::kRetimed;
  facts.records = 40;
  facts.steps_back = 3;
  facts.duplicates = 1;
  facts.largest_step_back_s = 0.25;
  facts.changed = 4;
  facts.largest_change_s = 0.125;
  facts.order_check = RecordOrderCheck{5, 4, 1, 3, 2};
  sequence.stamp_facts = facts;
  return sequence;
}

void ExpectSame(const Sequence& a, const Sequence& b) {
  EXPECT_EQ(EncodeSequence(a), EncodeSequence(b));
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.scans.size(), b.scans.size());
  EXPECT_EQ(a.scans[1].ranges_m, b.scans[1].ranges_m);
  EXPECT_EQ(a.scans[1].stamp_s, b.scans[1].stamp_s);
  EXPECT_EQ(a.odometry.stamps_s(), b.odometry.stamps_s());
  EXPECT_TRUE(a.odometry.poses()[1].position.isApprox(b.odometry.poses()[1].position, 0.0));
  EXPECT_EQ(a.odometry_readings.size(), b.odometry_readings.size());
  ASSERT_TRUE(b.reference && b.relations && b.reference_map);
  EXPECT_EQ(a.relations->front().t2_s, b.relations->front().t2_s);
  EXPECT_EQ(a.reference_map->cells, b.reference_map->cells);
  EXPECT_EQ(a.reference_map->origin.yaw_rad, b.reference_map->origin.yaw_rad);
  EXPECT_EQ(a.provenance.notes, b.provenance.notes);
  EXPECT_EQ(a.warnings, b.warnings);
  EXPECT_EQ(a.relations_outside_log, b.relations_outside_log);
  ASSERT_TRUE(b.stamp_facts.has_value());
  EXPECT_EQ(StampFactsJson(*a.stamp_facts), StampFactsJson(*b.stamp_facts));
}

TEST(SequenceCodecTest, EveryFieldSurvivesTheRoundTrip) {
  const Sequence sequence = EveryFieldSet();
  ExpectSame(sequence, DecodeSequence(EncodeSequence(sequence)));
  const Sequence empty;
  const Sequence decoded = DecodeSequence(EncodeSequence(empty));
  EXPECT_FALSE(decoded.reference || decoded.relations || decoded.reference_map || decoded.stamp_facts);
  EXPECT_EQ(decoded.relations_outside_log, 0u);
}

TEST(SequenceCodecTest, DamagedBytesAreAnInternalErrorNotACrash) {
  const std::string bytes = EncodeSequence(EveryFieldSet());
  for (std::size_t cut : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1}) {
    EXPECT_THROW(DecodeSequence(std::string_view(bytes).substr(0, cut)), std::runtime_error) << cut;
  }
  EXPECT_THROW(DecodeSequence(bytes + "x"), std::runtime_error);
  // A count of 2^64 - 1 scans is refused before anything is allocated for them.
  std::string huge = bytes;
  huge.replace(8 + EveryFieldSet().name.size(), 8, std::string(8, '\xff'));
  EXPECT_THROW(DecodeSequence(huge), std::runtime_error);
}

// Wall-clock time generous enough for a loaded machine, where a second of CPU can take many seconds.
ReaderLimits Small() { return {.memory_bytes = 64u << 20, .cpu_s = 1.0, .wall_s = 300.0}; }

std::string InputErrorOf(const std::function<ModuleOutcome(Sequence&)>& read, const ReaderLimits& limits = Small()) {
  try {
    ReadContained("/data/run.rawlog", "the test reader", limits, read);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

TEST(ContainedReadTest, TheSequenceReadInTheChildComesBackWhole) {
  const Sequence expected = EveryFieldSet();
  const pid_t parent = ::getpid();
  const Sequence got = ReadContained("/data/run.rawlog", "the test reader", Small(), [&](Sequence& sequence) {
    sequence = EveryFieldSet();
    // Read in another process, not this one.
    if (::getpid() == parent) sequence.name = "read in the parent";
    return ModuleOutcome{};
  });
  ExpectSame(expected, got);
}

TEST(ContainedReadTest, BadInputReportedByTheReaderIsAnInputErrorWithItsMessage) {
  EXPECT_EQ(InputErrorOf([](Sequence&) {
              return ModuleOutcome{ModuleOutcome::Kind::kInputError, "/data/run.rawlog: object 3 cannot be read"};
            }),
            "/data/run.rawlog: object 3 cannot be read");
}

TEST(ContainedReadTest, AnAllocationBeyondTheMemoryLimitIsAnInputErrorNamingTheLimit) {
  const std::string message = InputErrorOf([](Sequence&) {
    std::vector<char> huge(std::size_t{8} << 30, 'x');
    return ModuleOutcome{ModuleOutcome::Kind::kOk, std::string(1, huge[12345])};
  });
  EXPECT_THAT(message, HasSubstr("/data/run.rawlog"));
  EXPECT_THAT(message, HasSubstr("the test reader needs more than"));
  EXPECT_THAT(message, HasSubstr("of memory"));
}

TEST(ContainedReadTest, AReaderThatComputesForeverIsStoppedByItsCpuLimit) {
  const std::string message = InputErrorOf([](Sequence&) {
    volatile unsigned long spin = 0;
    while (true) spin = spin + 1;
    return ModuleOutcome{};
  });
  EXPECT_THAT(message, HasSubstr("took more than 1 s of CPU time"));
}

TEST(ContainedReadTest, AReaderThatWaitsForeverIsStoppedByItsWallClockLimit) {
  const std::string message = InputErrorOf(
      [](Sequence&) {
        std::this_thread::sleep_for(std::chrono::hours(1));
        return ModuleOutcome{};
      },
      {.memory_bytes = 64u << 20, .cpu_s = 1.0, .wall_s = 1.0});
  EXPECT_THAT(message, HasSubstr("did not finish reading it within 1 s"));
}

TEST(ContainedReadTest, ACrashOfTheLibraryIsAnInputErrorNamingTheSignal) {
  const std::string message = InputErrorOf([](Sequence&) -> ModuleOutcome { std::abort(); });
  EXPECT_THAT(message, HasSubstr("the test reader crashed reading it (signal 6"));
}

// A read of memory that is not there (as a library reading past its buffer into an unmapped page): a crash
// of the library, named as such, in every build. AddressSanitizer catches the signal and exits instead of
// dying by it; the child reports that as the crash it is, not as an error of ours.
TEST(ContainedReadTest, AWildReadIsAnInputErrorNamingTheCrash) {
  const std::string message = InputErrorOf([](Sequence&) -> ModuleOutcome {
    void* page = ::mmap(nullptr, 4096, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    return ModuleOutcome{ModuleOutcome::Kind::kOk, std::string(1, *static_cast<volatile char*>(page))};
  });
  EXPECT_THAT(message, HasSubstr("/data/run.rawlog"));
  EXPECT_THAT(message, HasSubstr("the test reader crashed reading it ("));
}

TEST(ContainedReadTest, AnInternalErrorOfTheReaderStaysAnInternalError) {
  EXPECT_THROW(ReadContained("/data/run.rawlog", "the test reader", Small(),
                             [](Sequence&) {
                               return ModuleOutcome{ModuleOutcome::Kind::kInternalError, "module out of step"};
                             }),
               std::runtime_error);
  try {
    ReadContained("/data/run.rawlog", "the test reader", Small(), [](Sequence&) -> ModuleOutcome { ::_exit(3); });
    FAIL() << "expected an error";
  } catch (const InputError&) {
    FAIL() << "a reader that ends without a word is not bad input";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), HasSubstr("without a result"));
  }
}

TEST(ContainedReadTest, LimitsGrowWithTheContent) {
  const ReaderLimits small = LimitsForContent(0);
  const ReaderLimits large = LimitsForContent(std::uintmax_t{100} << 20);
  EXPECT_GE(small.memory_bytes, std::uintmax_t{32} << 20);
  EXPECT_EQ(large.memory_bytes - small.memory_bytes, std::uintmax_t{1600} << 20);
  EXPECT_EQ(small.cpu_s, 10.0);
  EXPECT_EQ(large.cpu_s, 210.0);
  EXPECT_EQ(large.wall_s, 4 * 210.0 + 10.0);
}

}  // namespace
}  // namespace slamsweep::evaluator
