#include "evaluator/map_compare/map_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <tuple>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator::inline map_compare {
namespace {

enum Cell : std::uint8_t { kUnknownCell = 0, kFreeCell = 1, kOccupiedCell = 2 };

Cell Classify(float p, const MapCompareOptions& options) {
  if (OccupancyGrid::IsUnknown(p)) return kUnknownCell;
  if (p >= options.occupied_threshold) return kOccupiedCell;
  if (p <= options.free_threshold) return kFreeCell;
  return kUnknownCell;
}

/// Classify over a run of cells, without branches so that the loop vectorises. The thresholds
/// become the floats that compare with a cell exactly as the double thresholds do (p >= occupied
/// holds for a float p exactly when it holds in double), so the classes are Classify's.
void ClassifyRow(const float* p, std::size_t n, const MapCompareOptions& options, std::uint8_t* out) {
  float occupied = static_cast<float>(options.occupied_threshold);
  if (static_cast<double>(occupied) < options.occupied_threshold) {
    occupied = std::nextafter(occupied, std::numeric_limits<float>::infinity());
  }
  float free = static_cast<float>(options.free_threshold);
  if (static_cast<double>(free) > options.free_threshold)
    free = std::nextafter(free, -std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t is_occupied = p[i] >= occupied;
    const std::uint8_t is_free = (p[i] >= 0.0f) & (p[i] <= free) & (is_occupied ^ 1);
    out[i] = static_cast<std::uint8_t>(2 * is_occupied + is_free);
  }
}

/// The comparison canvas: the reference's cell lattice, wide enough for both maps.
struct Canvas {
  double origin_x = 0, origin_y = 0, resolution = 0;
  int width = 0, height = 0;
  double CenterX(int col) const { return origin_x + (col + 0.5) * resolution; }
  double CenterY(int row) const { return origin_y + (height - 1 - row + 0.5) * resolution; }
};

struct Point2 {
  double x, y;
};

Point2 Apply(const MapTransform& t, double x, double y) {
  const double c = std::cos(t.yaw_rad), s = std::sin(t.yaw_rad);
  return {t.x_m + c * x - s * y, t.y_m + s * x + c * y};
}

MapTransform Inverse(const MapTransform& t) {
  const double c = std::cos(t.yaw_rad), s = std::sin(t.yaw_rad);
  return {-(c * t.x_m + s * t.y_m), -(-s * t.x_m + c * t.y_m), -t.yaw_rad};
}

Canvas MakeCanvas(const OccupancyGrid& estimate, const OccupancyGrid& reference, const MapTransform& transform,
                  int padding_cells) {
  const double res = reference.resolution_m;
  double min_x = reference.origin.x_m, min_y = reference.origin.y_m;
  double max_x = min_x + reference.width * res, max_y = min_y + reference.height * res;
  const double ew = estimate.width * estimate.resolution_m, eh = estimate.height * estimate.resolution_m;
  for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {ew, 0.0}, {0.0, eh}, {ew, eh}}) {
    const Point2 p = Apply(transform, estimate.origin.x_m + dx, estimate.origin.y_m + dy);
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  Canvas canvas;
  canvas.resolution = res;
  // On the reference's lattice, so reference cells map to canvas cells one to one.
  const double first_col = std::floor((min_x - reference.origin.x_m) / res) - padding_cells;
  const double first_row = std::floor((min_y - reference.origin.y_m) / res) - padding_cells;
  canvas.origin_x = reference.origin.x_m + first_col * res;
  canvas.origin_y = reference.origin.y_m + first_row * res;
  canvas.width = static_cast<int>(std::ceil((max_x - canvas.origin_x) / res)) + padding_cells;
  canvas.height = static_cast<int>(std::ceil((max_y - canvas.origin_y) / res)) + padding_cells;
  return canvas;
}

cv::Mat RasterReference(const OccupancyGrid& reference, const Canvas& canvas, const MapCompareOptions& options) {
  cv::Mat out(canvas.height, canvas.width, CV_8U, cv::Scalar(kUnknownCell));
  const int col0 = static_cast<int>(std::lround((reference.origin.x_m - canvas.origin_x) / canvas.resolution));
  const int row0 = canvas.height - reference.height -
                   static_cast<int>(std::lround((reference.origin.y_m - canvas.origin_y) / canvas.resolution));
  for (int r = 0; r < reference.height; ++r) {
    ClassifyRow(&reference.cells[static_cast<std::size_t>(r) * reference.width],
                static_cast<std::size_t>(reference.width), options, out.ptr<std::uint8_t>(row0 + r) + col0);
  }
  return out;
}

/// Each canvas cell takes the class of the estimate cell under its centre (nearest neighbour).
cv::Mat RasterEstimate(const OccupancyGrid& estimate, const MapTransform& transform, const Canvas& canvas,
                       const MapCompareOptions& options) {
  // The estimate's classes once, so that the canvas loop only looks bytes up.
  std::vector<std::uint8_t> classes(estimate.cells.size());
  ClassifyRow(estimate.cells.data(), classes.size(), options, classes.data());
  cv::Mat out(canvas.height, canvas.width, CV_8U, cv::Scalar(kUnknownCell));
  const MapTransform to_estimate = Inverse(transform);
  const double c = std::cos(to_estimate.yaw_rad), s = std::sin(to_estimate.yaw_rad);
  const double inv_res = 1.0 / estimate.resolution_m;
  // In estimate cell units (column u, row from the bottom v), a canvas row is a straight line:
  // u = u0 + col du, v = v0 + col dv.
  const double du = c * canvas.resolution * inv_res, dv = s * canvas.resolution * inv_res;
  const double x0 = canvas.CenterX(0);
  for (int r = 0; r < canvas.height; ++r) {
    auto* row = out.ptr<std::uint8_t>(r);
    const double y = canvas.CenterY(r);
    const double u0 = (to_estimate.x_m + c * x0 - s * y - estimate.origin.x_m) * inv_res;
    const double v0 = (to_estimate.y_m + s * x0 + c * y - estimate.origin.y_m) * inv_res;
    // The columns whose centre falls on the estimate: 0 <= u0 + col du < width, the same for v
    // (found from the line, then checked cell by cell at the two ends against rounding).
    double first = 0.0, last = canvas.width - 1.0;
    for (const auto& [start, step, size] : {std::tuple{u0, du, estimate.width}, std::tuple{v0, dv, estimate.height}}) {
      if (step == 0.0) {
        if (start < 0.0 || start >= size) first = 1.0, last = 0.0;
        continue;
      }
      const double a = -start / step, b = (size - start) / step;
      first = std::max(first, std::floor(std::min(a, b)) - 1.0);
      last = std::min(last, std::ceil(std::max(a, b)) + 1.0);
    }
    if (first > last) continue;
    for (int col = static_cast<int>(first); col <= static_cast<int>(last); ++col) {
      const double u = u0 + col * du, v = v0 + col * dv;
      // Truncation is floor here: negative positions are rejected first.
      if (u < 0.0 || v < 0.0 || u >= estimate.width || v >= estimate.height) continue;
      const int ec = static_cast<int>(u), from_bottom = static_cast<int>(v);
      row[col] = classes[static_cast<std::size_t>(estimate.height - 1 - from_bottom) * estimate.width + ec];
    }
  }
  return out;
}

/// The exact Euclidean distance (in cells) from any cell to the nearest occupied cell of a class
/// image, evaluated only where asked: the occupied cells of the other map are a few percent of
/// the canvas, so a full distance transform of both maps would be most of the work. The first
/// pass of Felzenszwalb and Huttenlocher's separable transform gives every cell its distance to
/// the nearest occupied cell of its own column; a query then scans its row outwards until no
/// column can be nearer (dx^2 >= best), and a row whose queries scan far gets the exact lower
/// envelope of the second pass once. Squared distances are integers, so the result is exact.
template <typename Distance>
class OccupiedDistance {
 public:
  explicit OccupiedDistance(const cv::Mat& classes)
      : rows_(classes.rows), cols_(classes.cols), far_(static_cast<Distance>(classes.rows + classes.cols + 1)) {
    column_.resize(static_cast<std::size_t>(rows_) * cols_);
    envelopes_.resize(static_cast<std::size_t>(rows_));
    // Down the columns, all of them at once row by row (vectorised): distance to the nearest
    // occupied cell above, then below.
    const auto* first = classes.ptr<std::uint8_t>(0);
    for (int c = 0; c < cols_; ++c) column_[static_cast<std::size_t>(c)] = first[c] == kOccupiedCell ? 0 : far_;
    for (int r = 1; r < rows_; ++r) {
      const auto* cls = classes.ptr<std::uint8_t>(r);
      Distance* g = &column_[static_cast<std::size_t>(r) * cols_];
      const Distance* above = g - cols_;
      for (int c = 0; c < cols_; ++c) {
        const Distance next = std::min<Distance>(static_cast<Distance>(above[c] + 1), far_);
        g[c] = cls[c] == kOccupiedCell ? Distance{0} : next;
      }
    }
    for (int r = rows_ - 2; r >= 0; --r) {
      Distance* g = &column_[static_cast<std::size_t>(r) * cols_];
      const Distance* below = g + cols_;
      for (int c = 0; c < cols_; ++c) g[c] = std::min<Distance>(g[c], static_cast<Distance>(below[c] + 1));
    }
  }

  /// Squared distance in cells^2 (more than any distance on the canvas when the image has no occupied cell).
  double SquaredAt(int row, int col) {
    const Distance* g = &column_[static_cast<std::size_t>(row) * cols_];
    double best = Square(g[col]);
    for (int dx = 1; static_cast<double>(dx) * dx < best; ++dx) {
      if (dx > kScanLimit) return Envelope(row)[static_cast<std::size_t>(col)];
      const bool left = col - dx >= 0, right = col + dx < cols_;
      if (!left && !right) break;
      const double dx2 = static_cast<double>(dx) * dx;
      if (left) best = std::min(best, dx2 + Square(g[col - dx]));
      if (right) best = std::min(best, dx2 + Square(g[col + dx]));
    }
    return best;
  }

 private:
  static constexpr int kScanLimit = 64;
  static double Square(Distance v) { return static_cast<double>(v) * v; }

  /// The second pass for one row: d(x) = min over x' of (x - x')^2 + g(x')^2 (lower envelope of parabolas).
  const std::vector<double>& Envelope(int row) {
    std::vector<double>& d = envelopes_[static_cast<std::size_t>(row)];
    if (!d.empty()) return d;
    const Distance* g = &column_[static_cast<std::size_t>(row) * cols_];
    const auto f = [&](int x) { return Square(g[x]); };
    std::vector<int> v(static_cast<std::size_t>(cols_));
    std::vector<double> z(static_cast<std::size_t>(cols_) + 1);
    const auto boundary = [&](int q, int p) {
      return ((f(q) + static_cast<double>(q) * q) - (f(p) + static_cast<double>(p) * p)) / (2.0 * (q - p));
    };
    std::size_t k = 0;
    v[0] = 0;
    z[0] = -std::numeric_limits<double>::infinity();
    z[1] = std::numeric_limits<double>::infinity();
    for (int q = 1; q < cols_; ++q) {
      double at = boundary(q, v[k]);
      while (at <= z[k]) at = boundary(q, v[--k]);  // z[0] = -inf stops it
      ++k;
      v[k] = q;
      z[k] = at;
      z[k + 1] = std::numeric_limits<double>::infinity();
    }
    d.resize(static_cast<std::size_t>(cols_));
    k = 0;
    for (int x = 0; x < cols_; ++x) {
      while (z[k + 1] < x) ++k;
      const int p = v[k];
      d[static_cast<std::size_t>(x)] = static_cast<double>(x - p) * (x - p) + f(p);
    }
    return d;
  }

  int rows_, cols_;
  /// "No occupied cell in this column": longer than any distance on the canvas, and small enough
  /// that its square plus a column offset squared stays exact in a double. Distance must hold it
  /// plus one.
  Distance far_;
  std::vector<Distance> column_;
  std::vector<std::vector<double>> envelopes_;
};

struct Directed {
  double mean = 0, max = 0, within = 0;
  std::size_t count = 0;
};

/// Accumulates the distances of one direction (cells), then turns them into mean, max and the share within the radius.
struct DirectedSum {
  double sum = 0, max = 0;
  std::size_t count = 0, within = 0;
  void Add(double squared, double radius_squared) {
    const double distance = std::sqrt(squared);
    ++count;
    sum += distance;
    max = std::max(max, distance);
    within += squared <= radius_squared;
  }
  Directed Result() const {
    Directed d;
    d.count = count;
    d.max = max;
    if (count > 0) d.mean = sum / count, d.within = static_cast<double>(within) / count;
    return d;
  }
};

/// Point-to-point ICP of the estimate's occupied cells onto the reference's, nearest neighbours from
/// a labelled distance transform of the reference, closed-form rigid fit per iteration.
MapTransform RefineWithIcp(const OccupancyGrid& estimate, const OccupancyGrid& reference, MapTransform transform,
                           const MapCompareOptions& options) {
  std::vector<Point2> points;
  for (int r = 0; r < estimate.height; ++r) {
    for (int c = 0; c < estimate.width; ++c) {
      if (Classify(estimate.at(r, c), options) == kOccupiedCell)
        points.push_back({estimate.CellCenterXM(c), estimate.CellCenterYM(r)});
    }
  }
  constexpr int kPadding = 200;  // cells around the reference in which a nearest neighbour is looked up
  Canvas canvas;
  canvas.resolution = reference.resolution_m;
  canvas.origin_x = reference.origin.x_m - kPadding * canvas.resolution;
  canvas.origin_y = reference.origin.y_m - kPadding * canvas.resolution;
  canvas.width = reference.width + 2 * kPadding;
  canvas.height = reference.height + 2 * kPadding;
  const cv::Mat classes = RasterReference(reference, canvas, options);
  cv::Mat distance, labels;
  cv::distanceTransform(classes != kOccupiedCell, distance, labels, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  std::vector<Point2> by_label(1);  // labels count the zero (occupied) pixels from 1 in scan order
  for (int r = 0; r < classes.rows; ++r) {
    for (int c = 0; c < classes.cols; ++c) {
      if (classes.at<std::uint8_t>(r, c) == kOccupiedCell) by_label.push_back({canvas.CenterX(c), canvas.CenterY(r)});
    }
  }
  for (int iteration = 0; iteration < options.icp_iterations; ++iteration) {
    // Wide pairing first, then only close pairs: a coarse start converges, outliers stop pulling late.
    const double max_pair_m = iteration < options.icp_iterations / 2 ? 1.0 : 0.3;
    double sx = 0, sy = 0, tx = 0, ty = 0;
    std::vector<std::pair<Point2, Point2>> pairs;
    for (const Point2& p : points) {
      const Point2 moved = Apply(transform, p.x, p.y);
      const int c = static_cast<int>(std::floor((moved.x - canvas.origin_x) / canvas.resolution));
      const int r = canvas.height - 1 - static_cast<int>(std::floor((moved.y - canvas.origin_y) / canvas.resolution));
      if (c < 0 || c >= canvas.width || r < 0 || r >= canvas.height) continue;
      if (distance.at<float>(r, c) * canvas.resolution > max_pair_m) continue;
      const int label = labels.at<int>(r, c);
      if (label <= 0 || label >= static_cast<int>(by_label.size())) continue;
      pairs.push_back({moved, by_label[label]});
      sx += moved.x, sy += moved.y, tx += by_label[label].x, ty += by_label[label].y;
    }
    if (pairs.size() < 3) break;
    const double n = static_cast<double>(pairs.size());
    sx /= n, sy /= n, tx /= n, ty /= n;
    double sxx = 0, sxy = 0, syx = 0, syy = 0;
    for (const auto& [a, b] : pairs) {
      sxx += (a.x - sx) * (b.x - tx), sxy += (a.x - sx) * (b.y - ty);
      syx += (a.y - sy) * (b.x - tx), syy += (a.y - sy) * (b.y - ty);
    }
    const double angle = std::atan2(sxy - syx, sxx + syy);
    const double c = std::cos(angle), s = std::sin(angle);
    const MapTransform step{tx - (c * sx - s * sy), ty - (s * sx + c * sy), angle};
    // transform <- step * transform
    const Point2 t = Apply(step, transform.x_m, transform.y_m);
    transform = {t.x, t.y, transform.yaw_rad + angle};
    if (std::abs(angle) < 1e-7 && std::hypot(step.x_m, step.y_m) < 1e-6) break;
  }
  // Pairing with cell centres has fixed points up to a cell away from the optimum (long walls
  // sliding along themselves pull the other way): polish the translation on a quarter-cell grid
  // within 1.5 cells, by the mean (capped) distance to the reference's walls, bilinearly interpolated.
  cv::Mat precise;
  cv::distanceTransform(classes != kOccupiedCell, precise, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const auto mean_distance = [&](const MapTransform& candidate) {
    double sum = 0;
    for (const Point2& p : points) {
      const Point2 moved = Apply(candidate, p.x, p.y);
      const double fx = (moved.x - canvas.origin_x) / canvas.resolution - 0.5;
      const double fy = canvas.height - 1 - ((moved.y - canvas.origin_y) / canvas.resolution - 0.5);
      const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
      if (x0 < 0 || y0 < 0 || x0 + 1 >= precise.cols || y0 + 1 >= precise.rows) {
        sum += 3.0;
        continue;
      }
      const double ax = fx - x0, ay = fy - y0;
      const double d = (1 - ay) * ((1 - ax) * precise.at<float>(y0, x0) + ax * precise.at<float>(y0, x0 + 1)) +
                       ay * ((1 - ax) * precise.at<float>(y0 + 1, x0) + ax * precise.at<float>(y0 + 1, x0 + 1));
      sum += std::min(d, 3.0);
    }
    return sum / std::max<std::size_t>(points.size(), 1);
  };
  MapTransform best = transform;
  double best_score = mean_distance(transform);
  for (int i = -6; i <= 6; ++i) {
    for (int j = -6; j <= 6; ++j) {
      const MapTransform candidate{transform.x_m + i * canvas.resolution / 4, transform.y_m + j * canvas.resolution / 4,
                                   transform.yaw_rad};
      const double score = mean_distance(candidate);
      if (score < best_score - 1e-12) best = candidate, best_score = score;
    }
  }
  return best;
}

/// The scores of two rasterised maps (classes on one canvas) into `result`.
template <typename Distance>
MapComparison Measure(const Canvas& canvas, const cv::Mat& est, const cv::Mat& ref, const MapCompareOptions& options,
                      MapComparison result) {
  OccupiedDistance<Distance> to_reference_walls(ref), to_estimate_walls(est);
  DirectedSum to_reference_sum, to_estimate_sum;
  const double radius_squared = static_cast<double>(options.match_radius_cells) * options.match_radius_cells;
  // One pass over the canvas: each map's occupied cells ask for their distance to the other's,
  // and the cells known in both count for the IoUs.
  std::size_t both = 0, occ_and = 0, occ_or = 0, free_and = 0, free_or = 0;
  for (int r = 0; r < canvas.height; ++r) {
    const auto* a = est.ptr<std::uint8_t>(r);
    const auto* b = ref.ptr<std::uint8_t>(r);
    // Occupied cells are a few percent of a row: memchr finds them.
    for (const auto& [classes, walls, sum] :
         {std::tuple{a, &to_reference_walls, &to_reference_sum}, std::tuple{b, &to_estimate_walls, &to_estimate_sum}}) {
      const std::uint8_t* end = classes + canvas.width;
      for (const std::uint8_t* at = classes;
           (at = static_cast<const std::uint8_t*>(std::memchr(at, kOccupiedCell, static_cast<std::size_t>(end - at))));
           ++at) {
        sum->Add(walls->SquaredAt(r, static_cast<int>(at - classes)), radius_squared);
      }
    }
    // Branch-free counts over the cells known in both (vectorised).
    std::uint32_t row_both = 0, row_occ_and = 0, row_occ_or = 0, row_free_and = 0, row_free_or = 0;
    for (int c = 0; c < canvas.width; ++c) {
      const std::uint32_t known = (a[c] != kUnknownCell) & (b[c] != kUnknownCell);
      const std::uint32_t a_occ = a[c] == kOccupiedCell, b_occ = b[c] == kOccupiedCell;
      const std::uint32_t a_free = a[c] == kFreeCell, b_free = b[c] == kFreeCell;
      row_both += known;
      row_occ_and += known & a_occ & b_occ;
      row_occ_or += known & (a_occ | b_occ);
      row_free_and += known & a_free & b_free;
      row_free_or += known & (a_free | b_free);
    }
    both += row_both, occ_and += row_occ_and, occ_or += row_occ_or, free_and += row_free_and, free_or += row_free_or;
  }
  const Directed to_reference = to_reference_sum.Result();
  const Directed to_estimate = to_estimate_sum.Result();
  if (to_reference.count == 0) throw InputError("map-compare: the estimated map has no occupied cell");
  if (to_estimate.count == 0) throw InputError("map-compare: the reference map has no occupied cell");
  const double res = canvas.resolution;
  result.estimate_occupied = to_reference.count;
  result.reference_occupied = to_estimate.count;
  result.estimate_to_reference_mean_m = to_reference.mean * res;
  result.estimate_to_reference_max_m = to_reference.max * res;
  result.reference_to_estimate_mean_m = to_estimate.mean * res;
  result.reference_to_estimate_max_m = to_estimate.max * res;
  result.chamfer_m = 0.5 * (result.estimate_to_reference_mean_m + result.reference_to_estimate_mean_m);
  result.accuracy = to_reference.within;
  result.completeness = to_estimate.within;
  result.f1 = result.accuracy + result.completeness > 0
                  ? 2 * result.accuracy * result.completeness / (result.accuracy + result.completeness)
                  : 0.0;
  result.known_in_both = both;
  result.iou_occupied = occ_or > 0 ? static_cast<double>(occ_and) / occ_or : 0.0;
  result.iou_free = free_or > 0 ? static_cast<double>(free_and) / free_or : 0.0;
  return result;
}

}  // namespace

MapComparison CompareMaps(const OccupancyGrid& estimate, const OccupancyGrid& reference,
                          const MapCompareOptions& options) {
  if (std::abs(estimate.resolution_m - reference.resolution_m) > 0.01 * reference.resolution_m) {
    throw InputError("map-compare: the maps have different cell sizes (" + std::to_string(estimate.resolution_m) +
                     " m and " + std::to_string(reference.resolution_m) + " m); resample one first");
  }
  if (options.match_radius_cells < 0) throw InputError("map-compare: match radius must be >= 0 cells");
  MapComparison result;
  result.transform =
      options.refine_with_icp ? RefineWithIcp(estimate, reference, options.transform, options) : options.transform;
  const Canvas canvas = MakeCanvas(estimate, reference, result.transform, options.match_radius_cells + 1);
  const cv::Mat ref = RasterReference(reference, canvas, options);
  const cv::Mat est = RasterEstimate(estimate, result.transform, canvas, options);
  // 16-bit column distances (half the memory, twice the vector width) whenever they fit.
  const bool narrow = canvas.height + canvas.width + 2 <= std::numeric_limits<std::uint16_t>::max();
  return narrow ? Measure<std::uint16_t>(canvas, est, ref, options, result)
                : Measure<std::int32_t>(canvas, est, ref, options, result);
}

nlohmann::json MapComparison::ToJson(const MapCompareOptions& options) const {
  return {{"estimate_to_reference", {{"mean_m", estimate_to_reference_mean_m}, {"max_m", estimate_to_reference_max_m}}},
          {"reference_to_estimate", {{"mean_m", reference_to_estimate_mean_m}, {"max_m", reference_to_estimate_max_m}}},
          {"chamfer_m", chamfer_m},
          {"accuracy", accuracy},
          {"completeness", completeness},
          {"f1", f1},
          {"iou_occupied", iou_occupied},
          {"iou_free", iou_free},
          {"cells",
           {{"estimate_occupied", estimate_occupied},
            {"reference_occupied", reference_occupied},
            {"known_in_both", known_in_both}}},
          {"transform", {{"x_m", transform.x_m}, {"y_m", transform.y_m}, {"yaw_rad", transform.yaw_rad}}},
          {"specification",
           {{"occupied_threshold", options.occupied_threshold},
            {"free_threshold", options.free_threshold},
            {"match_radius_cells", options.match_radius_cells},
            {"alignment", options.refine_with_icp ? "icp" : "given"},
            {"distance", "exact Euclidean distance between occupied cells (separable distance transform)"}}}};
}

}  // namespace slamsweep::evaluator::inline map_compare
