#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

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

struct StampOptions {
  StampPolicy policy = StampPolicy::kAuto;
  /// Spacing of made-up stamps. 1 s makes a stamp read as the scan's index, and no SLAM program
  /// that slamsweep drives uses time for anything but ordering.
  double record_order_period_s = 1.0;
  /// kAuto keeps the recorded stamps while at most this fraction of them has to be repaired.
  /// The intel log (GMapping output) has 4 of 910 stamps a fraction of a second out of order;
  /// the broken logs have nearly all of them constant or decreasing.
  double max_repaired_fraction = 0.01;
  /// A stamp that does not come after its predecessor is lifted to predecessor + this.
  double repair_step_s = 1e-3;
};

/// Throws InputError naming the option when a value is out of range (periods > 0, fraction in [0, 1]).
void CheckStampOptions(const StampOptions& options);

enum class StampOutcome {
  /// Every recorded stamp kept as is.
  kRecorded,
  /// Recorded stamps, with the ones in `repaired` lifted to keep the order strict.
  kRepaired,
  /// Made-up stamps in record order.
  kRecordOrder,
};

struct ScanStamps {
  std::vector<double> stamps_s;
  StampOutcome outcome = StampOutcome::kRecorded;
  /// Indices whose recorded stamp did not come after the stamp chosen for the previous record.
  std::vector<std::size_t> non_increasing;
};

/// Chooses strictly increasing stamps for records in file order. Under kRecorded the result may
/// still contain `non_increasing` indices (stamps untouched): the caller reports the first one with
/// its file and line, which this function does not know. Pure. A non-finite stamp is an InputError.
ScanStamps ChooseScanStamps(std::span<const double> recorded_s, const StampOptions& options);

}  // namespace slamsweep::evaluator::inline sequence
