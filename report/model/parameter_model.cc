#include "report/model/parameter_model.h"

#include <algorithm>
#include <map>
#include <set>

namespace slamsweep::report::inline model {
namespace {

using nlohmann::json;

/// Numbers by value first, then booleans, then text, then anything else by its JSON; null first of all.
bool ValueLess(const json& a, const json& b) {
  const auto rank = [](const json& v) {
    return v.is_null() ? 0 : v.is_number() ? 1 : v.is_boolean() ? 2 : v.is_string() ? 3 : 4;
  };
  if (rank(a) != rank(b)) return rank(a) < rank(b);
  if (a.is_number()) return a.get<double>() < b.get<double>();
  if (a.is_boolean()) return !a.get<bool>() && b.get<bool>();
  return ParameterValueText(a) < ParameterValueText(b);
}

const json& ValueOf(const json& parameters, const std::string& name) {
  static const json kNull;
  const auto found = parameters.find(name);
  return found == parameters.end() ? kNull : *found;
}

std::size_t IndexOf(const ParameterAxis& axis, const json& value) {
  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (axis.values[i] == value) return i;
  }
  return axis.values.size();
}

}  // namespace

std::string ParameterValueText(const json& value) {
  if (value.is_null()) return "(not set)";
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

std::string SliceText(const ParameterSweep& sweep, const ParameterSlice& slice) {
  std::string text;
  for (std::size_t i = 0; i < sweep.sliced.size(); ++i) {
    text += (text.empty() ? "" : ", ") + sweep.sliced[i].name + "=" + ParameterValueText(slice.fixed[i]);
  }
  return text;
}

std::vector<std::size_t> ParameterSlice::Rows() const {
  std::vector<std::size_t> rows;
  for (const auto& line : cells) {
    for (const std::optional<std::size_t>& cell : line) {
      if (cell) rows.push_back(*cell);
    }
  }
  return rows;
}

std::optional<ParameterTable> BuildParameterTable(const SweepModel& model, const SequenceModel& sequence) {
  // Rows of each algorithm, with the parameter values of their runs (all runs of a row share them).
  std::map<std::string, std::vector<std::pair<std::size_t, const json*>>> by_algorithm;
  std::vector<std::string> order;  // table order of first appearance
  for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
    const AlgorithmRow& row = sequence.rows[r];
    if (row.runs.empty()) continue;
    if (by_algorithm.count(row.name) == 0) order.push_back(row.name);
    by_algorithm[row.name].emplace_back(r, &model.runs[row.runs.front()].parameter_values);
  }
  ParameterTable table;
  table.table_key = sequence.key;
  for (const std::string& algorithm : order) {
    const auto& rows = by_algorithm[algorithm];
    if (rows.size() < 2) continue;
    std::set<std::string> names;
    for (const auto& [r, parameters] : rows) {
      for (const auto& [name, value] : parameters->items()) names.insert(name);
    }
    std::vector<ParameterAxis> varying;
    std::string constant;
    for (const std::string& name : names) {
      ParameterAxis axis;
      axis.name = name;
      for (const auto& [r, parameters] : rows) {
        const json& value = ValueOf(*parameters, name);
        if (IndexOf(axis, value) == axis.values.size()) axis.values.push_back(value);
      }
      if (axis.values.size() < 2) {
        constant += (constant.empty() ? "" : "; ") + name + "=" + ParameterValueText(axis.values.front());
        continue;
      }
      std::sort(axis.values.begin(), axis.values.end(), ValueLess);
      axis.numeric = std::all_of(axis.values.begin(), axis.values.end(), [](const json& v) { return v.is_number(); });
      varying.push_back(std::move(axis));
    }
    if (varying.empty()) continue;  // rows that differ in nothing shown here (cannot happen for real groups)
    // The axes drawn: most values first, ties by name (stable sort over name order).
    std::stable_sort(varying.begin(), varying.end(),
                     [](const ParameterAxis& a, const ParameterAxis& b) { return a.values.size() > b.values.size(); });
    ParameterSweep sweep;
    sweep.algorithm = algorithm;
    sweep.constant = constant;
    const std::size_t drawn = std::min<std::size_t>(2, varying.size());
    sweep.axes.assign(varying.begin(), varying.begin() + static_cast<std::ptrdiff_t>(drawn));
    sweep.sliced.assign(varying.begin() + static_cast<std::ptrdiff_t>(drawn), varying.end());
    std::sort(sweep.sliced.begin(), sweep.sliced.end(),
              [](const ParameterAxis& a, const ParameterAxis& b) { return a.name < b.name; });

    const std::size_t width = sweep.axes[0].values.size();
    const std::size_t height = drawn == 2 ? sweep.axes[1].values.size() : 1;
    std::vector<ParameterSlice> slices;
    for (const auto& [r, parameters] : rows) {
      std::vector<json> fixed;
      for (const ParameterAxis& axis : sweep.sliced) fixed.push_back(ValueOf(*parameters, axis.name));
      auto slice =
          std::find_if(slices.begin(), slices.end(), [&](const ParameterSlice& s) { return s.fixed == fixed; });
      if (slice == slices.end()) {
        ParameterSlice created;
        created.fixed = fixed;
        created.cells.assign(height, std::vector<std::optional<std::size_t>>(width));
        slices.push_back(std::move(created));
        slice = slices.end() - 1;
      }
      const std::size_t x = IndexOf(sweep.axes[0], ValueOf(*parameters, sweep.axes[0].name));
      const std::size_t y = drawn == 2 ? IndexOf(sweep.axes[1], ValueOf(*parameters, sweep.axes[1].name)) : 0;
      slice->cells[y][x] = r;
    }
    std::sort(slices.begin(), slices.end(), [](const ParameterSlice& a, const ParameterSlice& b) {
      return std::lexicographical_compare(a.fixed.begin(), a.fixed.end(), b.fixed.begin(), b.fixed.end(), ValueLess);
    });
    sweep.slices = std::move(slices);
    table.sweeps.push_back(std::move(sweep));
  }
  if (table.sweeps.empty()) return std::nullopt;
  return table;
}

std::vector<ColumnRef> TableColumns(const SequenceModel& sequence) {
  std::vector<ColumnRef> columns;
  for (std::size_t c = 0; c < sequence.trajectory_columns.size(); ++c) columns.push_back({true, c});
  for (std::size_t c = 0; c < sequence.map_columns.size(); ++c) columns.push_back({false, c});
  return columns;
}

const MetricColumn& ColumnOf(const SequenceModel& sequence, const ColumnRef& column) {
  return column.trajectory ? sequence.trajectory_columns[column.index] : sequence.map_columns[column.index];
}

const MetricCell& CellOf(const AlgorithmRow& row, const ColumnRef& column) {
  return column.trajectory ? row.trajectory_cells[column.index] : row.map_cells[column.index];
}

BestValue FindBest(const SequenceModel& sequence, const std::vector<std::size_t>& rows, const ColumnRef& column) {
  std::vector<std::pair<double, std::size_t>> ranked;
  for (const std::size_t r : rows) {
    const AlgorithmRow& row = sequence.rows[r];
    const MetricCell& cell = CellOf(row, column);
    if (IsBestCandidate(row, ColumnOf(sequence, column), cell)) ranked.emplace_back(cell.summary.mean, r);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  BestValue best;
  if (ranked.empty()) return best;
  best.row = ranked[0].second;
  if (ranked.size() < 2) return best;
  best.runner_up = ranked[1].second;
  const MeanStd& a = CellOf(sequence.rows[*best.row], column).summary;
  const MeanStd& b = CellOf(sequence.rows[*best.runner_up], column).summary;
  best.tie = a.mean == b.mean;
  // Without a spread (one iteration) nothing tells a real difference from noise.
  best.clear = a.std && b.std && (b.mean - a.mean) > std::max(*a.std, *b.std);
  return best;
}

}  // namespace slamsweep::report::inline model
