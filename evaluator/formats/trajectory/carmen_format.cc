#include "evaluator/formats/trajectory/carmen_format.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/planarity.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

/// Why the stamps cannot be used (every reason found, joined), or nothing when they can.
std::optional<std::string> StampProblem(const std::vector<const CarmenLaserRecord*>& records,
                                        const CarmenReadOptions& options) {
  if (records.size() < 2) return std::nullopt;
  bool all_equal = true;
  std::size_t non_increasing = 0;
  const CarmenLaserRecord* jump_from = nullptr;
  const CarmenLaserRecord* jump_to = nullptr;
  for (std::size_t i = 1; i < records.size(); ++i) {
    const double step_s = records[i]->ipc_stamp_s - records[i - 1]->ipc_stamp_s;
    if (records[i]->ipc_stamp_s != records[0]->ipc_stamp_s) all_equal = false;
    if (step_s <= 0.0) ++non_increasing;
    if (jump_from == nullptr && std::abs(step_s) > options.max_plausible_step_s) {
      jump_from = records[i - 1];
      jump_to = records[i];
    }
  }
  if (all_equal) return fmt::format("all {} ipc_timestamps equal {} s", records.size(), records[0]->ipc_stamp_s);
  std::vector<std::string> reasons;
  const std::size_t steps = records.size() - 1;
  if (static_cast<double>(non_increasing) > options.max_non_increasing_fraction * static_cast<double>(steps)) {
    reasons.push_back(
        fmt::format("{} of {} consecutive ipc_timestamp steps do not increase, more than {}% "
                    "(repeated stamps: printed with too few digits?)",
                    non_increasing, steps, 100.0 * options.max_non_increasing_fraction));
  }
  if (jump_from != nullptr) {
    reasons.push_back(fmt::format(
        "ipc_timestamp jumps from {} s (line {}) to {} s (line {}), more than {} s "
        "(wrapped or corrupt clock?)",
        jump_from->ipc_stamp_s, jump_from->line, jump_to->ipc_stamp_s, jump_to->line, options.max_plausible_step_s));
  }
  if (reasons.empty()) return std::nullopt;
  return fmt::format("{}", fmt::join(reasons, "; "));
}

/// A note on stamps that go back in time but are kept (rare enough not to matter).
std::optional<std::string> BackwardStepsNote(const std::vector<const CarmenLaserRecord*>& records) {
  std::size_t backward = 0;
  double largest_s = 0.0;
  std::size_t largest_line = 0;
  for (std::size_t i = 1; i < records.size(); ++i) {
    const double step_s = records[i]->ipc_stamp_s - records[i - 1]->ipc_stamp_s;
    if (step_s > 0.0) continue;
    ++backward;
    if (-step_s >= largest_s) {
      largest_s = -step_s;
      largest_line = records[i]->line;
    }
  }
  if (backward == 0) return std::nullopt;
  return fmt::format(
      "{} of {} steps between laser records go back in time or repeat a stamp (largest step back "
      "{:.6g} s, at line {}); stamps kept",
      backward, records.size() - 1, largest_s, largest_line);
}

}  // namespace

void ValidateCarmenReadOptions(const CarmenReadOptions& options) {
  if (!(options.record_order_period_s > 0.0) || !std::isfinite(options.record_order_period_s)) {
    throw InputError("option record_order_period_s: expected a finite number > 0 s, got " +
                     ShortestText(options.record_order_period_s));
  }
  if (!(options.max_plausible_step_s > 0.0)) {
    throw InputError("option max_plausible_step_s: expected a number > 0 s, got " +
                     ShortestText(options.max_plausible_step_s));
  }
  if (!(options.max_non_increasing_fraction >= 0.0 && options.max_non_increasing_fraction <= 1.0)) {
    throw InputError("option max_non_increasing_fraction: expected a share in [0, 1], got " +
                     ShortestText(options.max_non_increasing_fraction));
  }
}

CarmenPoses CarmenPosesFromLog(const CarmenLog& log, const std::filesystem::path& source,
                               const CarmenReadOptions& options) {
  ValidateCarmenReadOptions(options);
  CarmenPoses result;
  std::vector<const CarmenLaserRecord*> flaser;
  std::vector<const CarmenLaserRecord*> robot_laser;
  for (const CarmenLaserRecord& record : log.lasers) {
    // RLASER (the rear laser) logs the same robot pose as its FLASER twin; it never adds poses.
    if (record.type == "FLASER") flaser.push_back(&record);
    if (record.type == "ROBOTLASER1") robot_laser.push_back(&record);
  }
  // A log may carry one scan as both messages; mixing them would double the poses.
  const std::vector<const CarmenLaserRecord*>& records = flaser.empty() ? robot_laser : flaser;
  if (records.empty()) {
    throw InputError(Located(source, 0, "no FLASER or ROBOTLASER1 records (expected a CARMEN log with laser scans)"));
  }
  if (!flaser.empty() && !robot_laser.empty()) {
    result.warnings.push_back(Located(source, 0,
                                      fmt::format("{} ROBOTLASER1 records ignored: the poses come from the {} FLASER "
                                                  "records",
                                                  robot_laser.size(), flaser.size())));
  }
  const std::optional<std::string> problem = StampProblem(records, options);
  result.used_record_order = problem.has_value();
  if (problem) {
    result.warnings.push_back(
        Located(source, 0,
                fmt::format("timestamps unusable ({}); poses stamped by record order instead (record index * {} s)",
                            *problem, options.record_order_period_s)));
  } else if (const std::optional<std::string> note = BackwardStepsNote(records)) {
    result.warnings.push_back(Located(source, 0, *note));
  }
  result.trajectory.Reserve(records.size());
  for (std::size_t i = 0; i < records.size(); ++i) {
    const double stamp_s =
        result.used_record_order ? static_cast<double>(i) * options.record_order_period_s : records[i]->ipc_stamp_s;
    result.trajectory.Add(stamp_s, records[i]->robot_pose);
  }
  return result;
}

CarmenPoses ReadCarmenPoses(const std::filesystem::path& path, const CarmenReadOptions& options) {
  ValidateCarmenReadOptions(options);
  return CarmenPosesFromLog(ReadCarmenLog(path), path, options);
}

void WriteCarmenPoses(const Trajectory& trajectory, std::ostream& out) {
  RequirePlanar(trajectory, "a CARMEN log (FLASER x y theta)");
  out << "# CARMEN log written by slamsweep: poses only (FLASER records without beams)\n";
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    CarmenLaserRecord record;
    record.type = "FLASER";
    record.robot_pose = trajectory.poses()[i];
    record.odom_pose = record.robot_pose;
    record.ipc_stamp_s = trajectory.stamps_s()[i];
    record.logger_stamp_s = record.ipc_stamp_s;
    record.ipc_host = "slamsweep";
    out << FormatCarmenRecord(record) << '\n';
  }
}

void WriteCarmenPoses(const Trajectory& trajectory, const std::filesystem::path& path) {
  WriteOutputFile(path, [&](std::ostream& out) { WriteCarmenPoses(trajectory, out); });
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
