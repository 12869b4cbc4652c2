#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/model/sweep_model.h"

namespace slamsweep::report::inline model {

/// A parameter that takes several values among one algorithm's rows of a table.
struct ParameterAxis {
  std::string name;
  /// Distinct values: numbers ascending, then booleans, then text; null stands for "not set".
  std::vector<nlohmann::json> values;
  bool numeric = false;  ///< every value is a number (a numeric x axis)
};

/// Rows of one algorithm that differ only in the drawn parameters: every other parameter is fixed,
/// so these rows, and only these, may be compared to name a best value.
struct ParameterSlice {
  /// The values of the parameters not drawn (three or more vary), in `ParameterSweep::sliced` order.
  std::vector<nlohmann::json> fixed;
  /// cells[y][x]: the row (index into SequenceModel::rows) run with the y-th value of axes[1] and the
  /// x-th value of axes[0]; one line of cells for one axis; empty where no such row exists.
  std::vector<std::vector<std::optional<std::size_t>>> cells;

  /// The rows of the slice, in x-then-y order.
  std::vector<std::size_t> Rows() const;
};

/// How one algorithm's parameter values vary in one table.
struct ParameterSweep {
  std::string algorithm;  ///< AlgorithmRow::name
  /// What is drawn: the x axis, and the y axis of a heatmap when two or more parameters vary (the
  /// parameters with the most values; ties by name).
  std::vector<ParameterAxis> axes;
  /// The parameters beyond two: one heatmap per combination of their values (a slice).
  std::vector<ParameterAxis> sliced;
  std::vector<ParameterSlice> slices;
  /// "name=value; ..." of the parameters the rows share ("" when none).
  std::string constant;
};

/// The parameter sweeps of one table (sequence x noise): one per algorithm whose rows vary.
struct ParameterTable {
  std::string table_key;
  std::vector<ParameterSweep> sweeps;
};

/// nullopt when no algorithm of the table has rows with different parameter values.
std::optional<ParameterTable> BuildParameterTable(const SweepModel& model, const SequenceModel& sequence);

/// A metric column of a table: Table I (trajectory) or the map metrics.
struct ColumnRef {
  bool trajectory = true;
  std::size_t index = 0;
};

/// The table's columns in display order (trajectory, then map).
std::vector<ColumnRef> TableColumns(const SequenceModel& sequence);
const MetricColumn& ColumnOf(const SequenceModel& sequence, const ColumnRef& column);
const MetricCell& CellOf(const AlgorithmRow& row, const ColumnRef& column);

/// The best of comparable rows for one metric: the lowest mean (every metric of the report is lower
/// is better) among rows with a value whose odometry is not the reference.
struct BestValue {
  std::optional<std::size_t> row;        ///< index into SequenceModel::rows
  std::optional<std::size_t> runner_up;  ///< the second lowest mean
  /// The runner-up's mean is further from the best than the larger of their standard deviations:
  /// otherwise the difference may be noise, and the page says so.
  bool clear = false;
  /// The runner-up's mean equals the best's: no single best value (figures mark none).
  bool tie = false;
};
BestValue FindBest(const SequenceModel& sequence, const std::vector<std::size_t>& rows, const ColumnRef& column);

/// A parameter value as the page shows it ("0.5", "true", "fast"; null is "(not set)").
std::string ParameterValueText(const nlohmann::json& value);

/// "c=1, d=fast": the values of the parameters not drawn in a slice ("" for one or two varying).
std::string SliceText(const ParameterSweep& sweep, const ParameterSlice& slice);

}  // namespace slamsweep::report::inline model
