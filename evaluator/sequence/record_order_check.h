#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/pose.h"

namespace slamsweep::evaluator::inline sequence {

/// Which order the records of a log with backward stamps were taken in: at every step where a recorded
/// stamp goes back (record i stamped before record i - 1), the two records' order in the file is weighed
/// against the order their stamps give, by how little consecutive records change in each: their scans
/// (mean absolute range difference over beams that hit in both) and their odometry (distance travelled).
/// A robot's consecutive scans and poses change least in the order it took them.
struct RecordOrderCheck {
  /// Backward steps weighed (those with a record on each side of the pair).
  std::size_t steps = 0;
  /// At how many the scans (the odometry) change less in file order, and at how many in stamp order.
  std::size_t scans_closer_in_file_order = 0;
  std::size_t scans_closer_in_stamp_order = 0;
  std::size_t odometry_shorter_in_file_order = 0;
  std::size_t odometry_shorter_in_stamp_order = 0;
};

/// `scans`, `odometry` and `recorded_stamps_s` are parallel, in file order. Pure.
RecordOrderCheck CheckRecordOrder(std::span<const LaserScan> scans, std::span<const Pose> odometry,
                                  std::span<const double> recorded_stamps_s);

/// {"steps", "scans_closer_in_file_order", ..., "odometry_shorter_in_stamp_order"}.
nlohmann::json RecordOrderCheckJson(const RecordOrderCheck& check);

}  // namespace slamsweep::evaluator::inline sequence
