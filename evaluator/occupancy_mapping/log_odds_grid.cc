#include "evaluator/occupancy_mapping/log_odds_grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline occupancy_mapping {
namespace {

// Cells store 2 * log-odds + 1 (log-odds in units of 1/kLogOddsScale), so every observed cell is
// odd and 0 means "never observed". An update is then add, clamp and set bit 0 (which turns an
// unobserved 0 into the first observation), with no test for unobserved cells in the inner loop.
constexpr std::int16_t kUnobserved = 0;
int Encode(int log_odds) { return 2 * log_odds + 1; }
int Decode(std::int16_t stored) { return stored >> 1; }

std::int16_t Quantize(double log_odds) { return static_cast<std::int16_t>(std::lround(log_odds * kLogOddsScale)); }

// A segment in continuous cell coordinates (x along columns, y upwards).
struct Segment {
  double x0, y0, x1, y1;
};

// Liang-Barsky clipping to [0, width] x [0, height]. Returns false when the segment misses the
// box; sets end_clipped when the far end had to be moved.
bool ClipToBox(Segment& s, double width, double height, bool& end_clipped) {
  const double dx = s.x1 - s.x0;
  const double dy = s.y1 - s.y0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {s.x0, width - s.x0, s.y0, height - s.y0};
  double t0 = 0.0, t1 = 1.0;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double r = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, r);
    } else {
      t1 = std::min(t1, r);
    }
  }
  if (t0 > t1) return false;
  end_clipped = t1 < 1.0;
  s = {s.x0 + t0 * dx, s.y0 + t0 * dy, s.x0 + t1 * dx, s.y0 + t1 * dy};
  return true;
}

int CellIndex(double coordinate, int size) { return std::clamp(static_cast<int>(std::floor(coordinate)), 0, size - 1); }

}  // namespace

LogOddsGrid::LogOddsGrid(const GridExtent& extent, const OccupancyMapperOptions& options)
    : extent_(extent),
      resolution_m_(options.resolution_m),
      max_range_m_(options.max_range_m),
      no_return_range_m_(options.no_return_range_m),
      hit_(Quantize(options.hit_log_odds)),
      miss_(Quantize(options.miss_log_odds)),
      min_(Quantize(options.min_log_odds)),
      max_(Quantize(options.max_log_odds)),
      log_odds_(static_cast<std::size_t>(extent.width_cells) * static_cast<std::size_t>(extent.height_cells),
                kUnobserved),
      changed_col_min_(extent.width_cells),
      changed_col_max_(-1),
      changed_row_min_(extent.height_cells),
      changed_row_max_(-1) {
  probability_.resize(static_cast<std::size_t>(max_ - min_) + 1);
  for (int value = min_; value <= max_; ++value) {
    probability_[static_cast<std::size_t>(value - min_)] =
        static_cast<float>(1.0 - 1.0 / (1.0 + std::exp(value / kLogOddsScale)));
  }
}

void LogOddsGrid::Integrate(const PlacedScan& placed, std::size_t scan_index) {
  if (placed.scan == nullptr) throw InputError("scan " + std::to_string(scan_index) + ": no scan given");
  const LaserScan& scan = *placed.scan;
  ValidateScanGeometry(scan, scan_index);
  directions_.Update(scan);
  const SensorPose2d sensor = SensorInWorld(placed.robot_pose, scan);
  const double width = extent_.width_cells;
  const double height = extent_.height_cells;
  const double inverse_resolution = 1.0 / resolution_m_;
  // Continuous cell coordinates, y upwards: cell (floor(x), floor(y)) is column floor(x) and
  // row height - 1 - floor(y), the same lattice as the extent (a point on a cell border belongs
  // to the cell above/right of it).
  const double x0 = (sensor.x_m - extent_.origin.x_m) * inverse_resolution;
  const double y0 = (sensor.y_m - extent_.origin.y_m) * inverse_resolution;
  const double cos_yaw = std::cos(sensor.yaw_rad);
  const double sin_yaw = std::sin(sensor.yaw_rad);
  if (!std::isfinite(x0) || !std::isfinite(y0)) {
    throw InputError("scan " + std::to_string(scan_index) + ": sensor position is too far from the map to trace");
  }
  const bool sensor_inside = x0 >= 0.0 && x0 < width && y0 >= 0.0 && y0 < height;

  const std::vector<double>& beam_cos = directions_.cos();
  const std::vector<double>& beam_sin = directions_.sin();
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const BeamUse use = UseBeam(scan, scan.ranges_m[i], max_range_m_, no_return_range_m_);
    if (!(use.length_m > 0.0)) continue;
    const double cells = use.length_m * inverse_resolution;
    const double dx = cos_yaw * beam_cos[i] - sin_yaw * beam_sin[i];
    const double dy = sin_yaw * beam_cos[i] + cos_yaw * beam_sin[i];
    Segment ray{x0, y0, x0 + cells * dx, y0 + cells * dy};
    bool marks_hit = use.marks_hit;
    const bool end_inside = ray.x1 >= 0.0 && ray.x1 < width && ray.y1 >= 0.0 && ray.y1 < height;
    if (!(sensor_inside && end_inside)) {
      bool end_clipped = false;
      if (!ClipToBox(ray, width, height, end_clipped)) continue;
      marks_hit = marks_hit && !end_clipped;
    }
    const int col0 = CellIndex(ray.x0, extent_.width_cells);
    const int row0 = extent_.height_cells - 1 - CellIndex(ray.y0, extent_.height_cells);
    const int col1 = CellIndex(ray.x1, extent_.width_cells);
    const int row1 = extent_.height_cells - 1 - CellIndex(ray.y1, extent_.height_cells);
    changed_col_min_ = std::min({changed_col_min_, col0, col1});
    changed_col_max_ = std::max({changed_col_max_, col0, col1});
    changed_row_min_ = std::min({changed_row_min_, row0, row1});
    changed_row_max_ = std::max({changed_row_max_, row0, row1});
    Trace(col0, row0, col1, row1, marks_hit);
  }
}

void LogOddsGrid::Trace(int col0, int row0, int col1, int row1, bool marks_hit) {
  // Everything is pointer-sized so that the inner loop needs no sign extensions.
  const std::ptrdiff_t col_distance = std::abs(col1 - col0);
  const std::ptrdiff_t row_distance = std::abs(row1 - row0);
  const std::ptrdiff_t width = extent_.width_cells;
  const std::ptrdiff_t col_step = col1 >= col0 ? 1 : -1;
  const std::ptrdiff_t row_step = row1 >= row0 ? width : -width;
  const bool cols_major = col_distance >= row_distance;
  const std::ptrdiff_t major_length = cols_major ? col_distance : row_distance;
  const std::ptrdiff_t minor_length = cols_major ? row_distance : col_distance;
  const std::ptrdiff_t major_step = cols_major ? col_step : row_step;
  const std::ptrdiff_t minor_step = cols_major ? row_step : col_step;
  const int miss = 2 * miss_;
  const int lowest = Encode(min_);

  // Integer DDA: one cell per step along the major axis; the minor coordinate advances by
  // minor/major cells per step in 32.32 fixed point and is rounded to the nearest cell (the cells
  // Bresenham's algorithm picks, up to how exact ties are broken). Unlike Bresenham's error
  // term, nothing in the loop depends on a comparison, so consecutive cells do not wait on
  // each other.
  std::int16_t* const start = log_odds_.data() + row0 * width + col0;
  if (major_length > 0) {
    const std::uint64_t slope =
        (static_cast<std::uint64_t>(minor_length) << 32) / static_cast<std::uint64_t>(major_length);
    std::uint64_t minor = std::uint64_t{1} << 31;  // half a cell: round to nearest
    std::ptrdiff_t major = 0;
    for (std::ptrdiff_t remaining = major_length; remaining > 0; --remaining) {
      std::int16_t* cell = start + major + static_cast<std::ptrdiff_t>(minor >> 32) * minor_step;
      *cell = static_cast<std::int16_t>(std::max(*cell + miss, lowest) | 1);
      major += major_step;
      minor += slope;
    }
  }
  std::int16_t* const end = log_odds_.data() + static_cast<std::ptrdiff_t>(row1) * width + col1;
  *end = marks_hit ? static_cast<std::int16_t>(std::min(*end + 2 * hit_, Encode(max_)) | 1)
                   : static_cast<std::int16_t>(std::max(*end + miss, lowest) | 1);
}

OccupancyGrid LogOddsGrid::MakeUnknownGrid() const {
  return OccupancyGrid(extent_.width_cells, extent_.height_cells, resolution_m_, extent_.origin);
}

void LogOddsGrid::WriteChangedCells(OccupancyGrid& grid) {
  for (int row = changed_row_min_; row <= changed_row_max_; ++row) {
    const std::size_t begin = static_cast<std::size_t>(row) * extent_.width_cells;
    for (int col = changed_col_min_; col <= changed_col_max_; ++col) {
      const std::int16_t value = log_odds_[begin + col];
      grid.cells[begin + col] =
          value == kUnobserved ? OccupancyGrid::kUnknown : probability_[static_cast<std::size_t>(Decode(value) - min_)];
    }
  }
  changed_col_min_ = extent_.width_cells;
  changed_col_max_ = -1;
  changed_row_min_ = extent_.height_cells;
  changed_row_max_ = -1;
}

}  // namespace slamsweep::evaluator::inline occupancy_mapping
