#include "evaluator/sequence/scan_stamps.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

std::vector<double> RecordOrder(std::size_t count, double period_s) {
  std::vector<double> stamps(count);
  for (std::size_t i = 0; i < count; ++i) stamps[i] = static_cast<double>(i) * period_s;
  return stamps;
}

}  // namespace

std::string_view StampPolicyName(StampPolicy policy) {
  switch (policy) {
    case StampPolicy::kAuto:
      return "auto";
    case StampPolicy::kRecorded:
      return "recorded";
    case StampPolicy::kRecordOrder:
      return "record_order";
  }
  return "auto";
}

StampPolicy ParseStampPolicy(std::string_view text, std::string_view option) {
  for (StampPolicy policy : {StampPolicy::kAuto, StampPolicy::kRecorded, StampPolicy::kRecordOrder}) {
    if (text == StampPolicyName(policy)) return policy;
  }
  throw InputError(
      fmt::format("{}: expected one of auto, recorded, record_order, got '{}'", option, std::string(text)));
}

void CheckStampOptions(const StampOptions& options) {
  if (!(options.record_order_period_s > 0.0) || !std::isfinite(options.record_order_period_s)) {
    throw InputError(
        fmt::format("record_order_period_s: expected a finite period > 0 s, got {}", options.record_order_period_s));
  }
  if (!(options.repair_step_s > 0.0) || !std::isfinite(options.repair_step_s)) {
    throw InputError(fmt::format("repair_step_s: expected a finite step > 0 s, got {}", options.repair_step_s));
  }
  if (!(options.max_repaired_fraction >= 0.0 && options.max_repaired_fraction <= 1.0)) {
    throw InputError(
        fmt::format("max_repaired_fraction: expected a value in [0, 1], got {}", options.max_repaired_fraction));
  }
}

ScanStamps ChooseScanStamps(std::span<const double> recorded_s, const StampOptions& options) {
  CheckStampOptions(options);
  for (std::size_t i = 0; i < recorded_s.size(); ++i) {
    if (!std::isfinite(recorded_s[i])) {
      throw InputError(fmt::format("record {}: stamp {} is not a finite number", i, recorded_s[i]));
    }
  }
  ScanStamps result;
  if (options.policy == StampPolicy::kRecordOrder) {
    result.stamps_s = RecordOrder(recorded_s.size(), options.record_order_period_s);
    result.outcome = StampOutcome::kRecordOrder;
    return result;
  }
  result.stamps_s.assign(recorded_s.begin(), recorded_s.end());
  for (std::size_t i = 1; i < result.stamps_s.size(); ++i) {
    if (result.stamps_s[i] > result.stamps_s[i - 1]) continue;
    result.non_increasing.push_back(i);
    // Lifting (not dropping or reordering) keeps every scan and its place in the log; the lift
    // cascades through any following stamps it overtakes, so the order stays strict.
    if (options.policy == StampPolicy::kAuto) result.stamps_s[i] = result.stamps_s[i - 1] + options.repair_step_s;
  }
  if (result.non_increasing.empty()) return result;
  if (options.policy == StampPolicy::kRecorded) {
    result.stamps_s.assign(recorded_s.begin(), recorded_s.end());
    return result;
  }
  const double fraction = static_cast<double>(result.non_increasing.size()) / static_cast<double>(recorded_s.size());
  if (fraction <= options.max_repaired_fraction) {
    result.outcome = StampOutcome::kRepaired;
  } else {
    result.stamps_s = RecordOrder(recorded_s.size(), options.record_order_period_s);
    result.outcome = StampOutcome::kRecordOrder;
  }
  return result;
}

}  // namespace slamsweep::evaluator::inline sequence
