#include "evaluator/occupancy_mapping/occupancy_mapper_options.h"

#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline occupancy_mapping {
namespace {

void Require(bool ok, const char* option, double value, const char* expected) {
  if (!ok) {
    throw InputError(std::string("occupancy mapper option ") + option + " = " + std::to_string(value) + ", expected " +
                     expected);
  }
}

bool InLogOddsRange(double value) { return std::isfinite(value) && std::abs(value) <= kMaxAbsLogOdds; }

}  // namespace

void ValidateMapperOptions(const OccupancyMapperOptions& options) {
  Require(std::isfinite(options.resolution_m) && options.resolution_m > 0.0, "resolution_m", options.resolution_m,
          "a finite number > 0");
  Require(InLogOddsRange(options.hit_log_odds) && options.hit_log_odds * kLogOddsScale >= 1.0, "hit_log_odds",
          options.hit_log_odds, "in [0.001, 16]");
  Require(InLogOddsRange(options.miss_log_odds) && options.miss_log_odds * kLogOddsScale <= -1.0, "miss_log_odds",
          options.miss_log_odds, "in [-16, -0.001]");
  Require(InLogOddsRange(options.min_log_odds) && options.min_log_odds < 0.0, "min_log_odds", options.min_log_odds,
          "in [-16, 0)");
  Require(InLogOddsRange(options.max_log_odds) && options.max_log_odds > 0.0, "max_log_odds", options.max_log_odds,
          "in (0, 16]");
  Require(std::isfinite(options.max_range_m) && options.max_range_m > 0.0, "max_range_m", options.max_range_m,
          "a finite number > 0");
  Require(std::isfinite(options.no_return_range_m) && options.no_return_range_m >= 0.0, "no_return_range_m",
          options.no_return_range_m, "a finite number >= 0");
  Require(std::isfinite(options.margin_m) && options.margin_m >= 0.0, "margin_m", options.margin_m,
          "a finite number >= 0");
  if (options.fixed_extent) {
    ValidateGridExtent(*options.fixed_extent, "occupancy mapper option fixed_extent");
    const long long cells =
        static_cast<long long>(options.fixed_extent->width_cells) * options.fixed_extent->height_cells;
    Require(cells <= kMaxMapCells, "fixed_extent (cells)", static_cast<double>(cells), "at most 200000000 cells");
  }
}

void to_json(nlohmann::json& out, const OccupancyMapperOptions& options) {
  out = nlohmann::json{{"resolution_m", options.resolution_m},
                       {"hit_log_odds", options.hit_log_odds},
                       {"miss_log_odds", options.miss_log_odds},
                       {"min_log_odds", options.min_log_odds},
                       {"max_log_odds", options.max_log_odds},
                       {"max_range_m", options.max_range_m},
                       {"no_return_range_m", options.no_return_range_m},
                       {"margin_m", options.margin_m},
                       {"fixed_extent", nullptr}};
  if (options.fixed_extent) out["fixed_extent"] = *options.fixed_extent;
}

}  // namespace slamsweep::evaluator::inline occupancy_mapping
