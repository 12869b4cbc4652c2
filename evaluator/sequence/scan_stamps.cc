#include "evaluator/sequence/scan_stamps.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline sequence {
namespace {

std::vector<double> RecordOrder(std::size_t count, double period_s) {
  std::vector<double> stamps(count);
  for (std::size_t i = 0; i < count; ++i) stamps[i] = static_cast<double>(i) * period_s;
  return stamps;
}

/// The indices of a longest strictly increasing subsequence of `stamps` (ascending). Patience sorting
/// with back links, O(n log n); among equally long ones it keeps, for every length, the one ending lowest,
/// and of equal stamps the first: a record that repeats an earlier stamp is the one re-timed.
std::vector<std::size_t> LongestIncreasingRun(std::span<const double> stamps) {
  std::vector<std::size_t> tails;  // tails[k]: the index ending the lowest increasing run of length k + 1
  std::vector<std::size_t> previous(stamps.size(), stamps.size());
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    const auto at = std::lower_bound(tails.begin(), tails.end(), stamps[i],
                                     [&](std::size_t index, double value) { return stamps[index] < value; });
    if (at != tails.end() && stamps[*at] == stamps[i]) continue;
    if (at != tails.begin()) previous[i] = *std::prev(at);
    if (at == tails.end()) {
      tails.push_back(i);
    } else {
      *at = i;
    }
  }
  std::vector<std::size_t> kept;
  for (std::size_t i = tails.empty() ? stamps.size() : tails.back(); i < stamps.size(); i = previous[i]) {
    kept.push_back(i);
  }
  std::reverse(kept.begin(), kept.end());
  return kept;
}

/// Keeps the stamps of `kept` and re-times the others linearly by index between their kept neighbours;
/// records before the first (after the last) kept one continue the spacing of the first (last) two kept
/// ones, or repair_step_s apart when only one is kept.
std::vector<double> Retimed(std::span<const double> recorded, const std::vector<std::size_t>& kept, double step_s) {
  std::vector<double> stamps(recorded.begin(), recorded.end());
  for (std::size_t k = 1; k < kept.size(); ++k) {
    const std::size_t a = kept[k - 1];
    const std::size_t b = kept[k];
    const double per_record = (recorded[b] - recorded[a]) / static_cast<double>(b - a);
    for (std::size_t j = a + 1; j < b; ++j) stamps[j] = recorded[a] + per_record * static_cast<double>(j - a);
  }
  const std::size_t first = kept.front();
  const std::size_t last = kept.back();
  const double head_step =
      kept.size() > 1 ? (recorded[kept[1]] - recorded[first]) / static_cast<double>(kept[1] - first) : step_s;
  const double tail_step = kept.size() > 1 ? (recorded[last] - recorded[kept[kept.size() - 2]]) /
                                                 static_cast<double>(last - kept[kept.size() - 2])
                                           : step_s;
  for (std::size_t j = 0; j < first; ++j) stamps[j] = recorded[first] - head_step * static_cast<double>(first - j);
  for (std::size_t j = last + 1; j < recorded.size(); ++j) {
    stamps[j] = recorded[last] + tail_step * static_cast<double>(j - last);
  }
  return stamps;
}

ScanStamps ChooseRetimed(std::span<const double> recorded_s, const StampOptions& options) {
  ScanStamps result;
  for (std::size_t i = 1; i < recorded_s.size(); ++i) {
    if (!(recorded_s[i] > recorded_s[i - 1])) result.non_increasing.push_back(i);
  }
  result.stamps_s.assign(recorded_s.begin(), recorded_s.end());
  if (result.non_increasing.empty() || options.policy == StampPolicy::kRecorded) return result;
  const std::vector<std::size_t> kept = LongestIncreasingRun(recorded_s);
  std::size_t next_kept = 0;
  for (std::size_t i = 0; i < recorded_s.size(); ++i) {
    if (next_kept < kept.size() && kept[next_kept] == i) {
      ++next_kept;
    } else {
      result.retimed.push_back(i);
    }
  }
  const double fraction = static_cast<double>(result.retimed.size()) / static_cast<double>(recorded_s.size());
  if (fraction <= options.max_retimed_fraction) {
    result.stamps_s = Retimed(recorded_s, kept, options.repair_step_s);
    result.outcome = StampOutcome::kRetimed;
  } else {
    result.stamps_s = RecordOrder(recorded_s.size(), options.record_order_period_s);
    result.outcome = StampOutcome::kRecordOrder;
    result.retimed.clear();
  }
  return result;
}

}  // namespace

std::string_view StampOutcomeName(StampOutcome outcome) {
  switch (outcome) {
    case StampOutcome::kRecorded:
      return "recorded";
    case StampOutcome::kRepaired:
      return "repaired";
    case StampOutcome::kRetimed:
      return "retimed";
    case StampOutcome::kRecordOrder:
      return "record_order";
  }
  return "recorded";
}

StampFacts DescribeStamps(std::span<const double> recorded_s, const ScanStamps& chosen) {
  StampFacts facts;
  facts.outcome = chosen.outcome;
  facts.records = recorded_s.size();
  for (std::size_t i = 1; i < recorded_s.size(); ++i) {
    const double step = recorded_s[i] - recorded_s[i - 1];
    if (step < 0.0) {
      ++facts.steps_back;
      facts.largest_step_back_s = std::max(facts.largest_step_back_s, -step);
    } else if (step == 0.0) {
      ++facts.duplicates;
    }
  }
  if (chosen.outcome == StampOutcome::kRecordOrder) {
    facts.changed = recorded_s.size();
    return facts;
  }
  for (std::size_t i = 0; i < recorded_s.size() && i < chosen.stamps_s.size(); ++i) {
    const double change = std::abs(chosen.stamps_s[i] - recorded_s[i]);
    if (change == 0.0) continue;
    ++facts.changed;
    facts.largest_change_s = std::max(facts.largest_change_s, change);
  }
  return facts;
}

nlohmann::json StampFactsJson(const StampFacts& facts) {
  nlohmann::json json{{"outcome", StampOutcomeName(facts.outcome)},
                      {"records", facts.records},
                      {"steps_back", facts.steps_back},
                      {"duplicates", facts.duplicates},
                      {"largest_step_back_s", facts.largest_step_back_s},
                      {"changed", facts.changed},
                      {"largest_change_s", facts.largest_change_s}};
  if (facts.order_check) json["order_check"] = RecordOrderCheckJson(*facts.order_check);
  return json;
}

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
  if (!(options.max_retimed_fraction >= 0.0 && options.max_retimed_fraction <= 1.0)) {
    throw InputError(
        fmt::format("max_retimed_fraction: expected a value in [0, 1], got {}", options.max_retimed_fraction));
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
  if (options.repair == StampRepair::kRetime) return ChooseRetimed(recorded_s, options);
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
