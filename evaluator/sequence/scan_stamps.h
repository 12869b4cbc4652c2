#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "evaluator/sequence/record_order_check.h"

namespace slamsweep::evaluator::inline sequence {

/// How a reader turns the stamps recorded in a log into scan stamps, which must strictly increase.
enum class StampPolicy {
  /// Recorded stamps when usable; isolated backward steps are repaired; a log whose stamps are
  /// degenerate (constant, zero, mostly non-increasing, wrapped) falls back to record order.
  kAuto,
  /// Recorded stamps or nothing: a stamp that does not increase is an error.
  kRecorded,
  /// Ignore the recorded stamps: record i gets i * record_order_period_s.
  kRecordOrder,
};

/// "auto", "recorded", "record_order".
std::string_view StampPolicyName(StampPolicy policy);
/// Inverse of StampPolicyName; InputError naming `option` and the accepted values otherwise.
StampPolicy ParseStampPolicy(std::string_view text, std::string_view option = "stamp_policy");

/// How kAuto repairs stamps that do not come after their predecessor in file order.
enum class StampRepair {
  /// Each such stamp is lifted to its predecessor + repair_step_s; a lift cascades through the stamps it
  /// overtakes. For logs with a few isolated backward steps (the corrected logs).
  kLift,
  /// The largest set of stamps that increase in file order is kept; every other stamp is re-timed
  /// linearly (by record index) between its kept neighbours. For raw logs whose scans are in acquisition
  /// order but some stamps arrived late: a late stamp moves alone instead of dragging the next ones along.
  kRetime,
};

struct StampOptions {
  StampPolicy policy = StampPolicy::kAuto;
  StampRepair repair = StampRepair::kLift;
  /// Spacing of made-up stamps. 1 s makes a stamp read as the scan's index, and no SLAM program
  /// that slamsweep drives uses time for anything but ordering.
  double record_order_period_s = 1.0;
  /// kAuto keeps the recorded stamps while at most this fraction of them has to be repaired.
  /// The intel log (GMapping output) has 4 of 910 stamps a fraction of a second out of order;
  /// the broken logs have nearly all of them constant or decreasing.
  double max_repaired_fraction = 0.01;
  /// A stamp that does not come after its predecessor is lifted to predecessor + this.
  double repair_step_s = 1e-3;
  /// With StampRepair::kRetime, kAuto keeps the recorded stamps while at most this fraction of them has
  /// to be re-timed. The full-rate intel run needs 323 of 5,505 (5.9 %); logs whose clocks are broken
  /// (constant or six-significant-digit stamps) need most of them.
  double max_retimed_fraction = 0.25;
};

/// Throws InputError naming the option when a value is out of range (periods > 0, fraction in [0, 1]).
void CheckStampOptions(const StampOptions& options);

enum class StampOutcome {
  /// Every recorded stamp kept as is.
  kRecorded,
  /// Recorded stamps, with the ones in `non_increasing` lifted to keep the order strict.
  kRepaired,
  /// Recorded stamps, with the ones in `retimed` re-timed between their kept neighbours.
  kRetimed,
  /// Made-up stamps in record order.
  kRecordOrder,
};

/// "recorded", "repaired", "retimed", "record_order".
std::string_view StampOutcomeName(StampOutcome outcome);

struct ScanStamps {
  std::vector<double> stamps_s;
  StampOutcome outcome = StampOutcome::kRecorded;
  /// Indices whose recorded stamp did not come after the stamp chosen for the previous record (kLift),
  /// or after the previous recorded stamp (kRetime).
  std::vector<std::size_t> non_increasing;
  /// kRetimed: the indices whose stamps were re-timed, ascending.
  std::vector<std::size_t> retimed;
};

/// What a log's recorded stamps look like in file order and what the reader did with them: the facts
/// `data info` prints and result.json keeps.
struct StampFacts {
  StampOutcome outcome = StampOutcome::kRecorded;
  std::size_t records = 0;
  /// Recorded stamps earlier than the previous record's, and equal to it.
  std::size_t steps_back = 0;
  std::size_t duplicates = 0;
  /// The largest step back, seconds (0 without any).
  double largest_step_back_s = 0.0;
  /// Stamps the reader changed (lifted or re-timed; all of them in record order), and by how much at most.
  std::size_t changed = 0;
  double largest_change_s = 0.0;
  /// Which order the records were taken in, weighed at the backward steps (raw CARMEN logs).
  std::optional<RecordOrderCheck> order_check;
};

/// The facts of `chosen` for `recorded_s` (the same records, file order).
StampFacts DescribeStamps(std::span<const double> recorded_s, const ScanStamps& chosen);

/// {"outcome", "records", "steps_back", "duplicates", "largest_step_back_s", "changed", "largest_change_s"}, and
/// "order_check" when there is one.
nlohmann::json StampFactsJson(const StampFacts& facts);

/// Chooses strictly increasing stamps for records in file order (options.repair says how kAuto repairs).
/// Under kRecorded the result may
/// still contain `non_increasing` indices (stamps untouched): the caller reports the first one with
/// its file and line, which this function does not know. Pure. A non-finite stamp is an InputError.
ScanStamps ChooseScanStamps(std::span<const double> recorded_s, const StampOptions& options);

}  // namespace slamsweep::evaluator::inline sequence
