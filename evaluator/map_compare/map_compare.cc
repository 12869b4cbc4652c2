#include "evaluator/map_compare/map_compare.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "evaluator/core/input_error.h"

namespace slamsweep::evaluator {
namespace {

enum Cell : std::uint8_t { kUnknownCell = 0, kFreeCell = 1, kOccupiedCell = 2 };

Cell Classify(float p, const MapCompareOptions& options) {
  if (OccupancyGrid::IsUnknown(p)) return kUnknownCell;
  if (p >= options.occupied_threshold) return kOccupiedCell;
  if (p <= options.free_threshold) return kFreeCell;
  return kUnknownCell;
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
    auto* row = out.ptr<std::uint8_t>(row0 + r);
    for (int c = 0; c < reference.width; ++c) row[col0 + c] = Classify(reference.at(r, c), options);
  }
  return out;
}

/// Each canvas cell takes the class of the estimate cell under its centre (nearest neighbour).
cv::Mat RasterEstimate(const OccupancyGrid& estimate, const MapTransform& transform, const Canvas& canvas,
                       const MapCompareOptions& options) {
  cv::Mat out(canvas.height, canvas.width, CV_8U, cv::Scalar(kUnknownCell));
  const MapTransform to_estimate = Inverse(transform);
  const double c = std::cos(to_estimate.yaw_rad), s = std::sin(to_estimate.yaw_rad);
  const double inv_res = 1.0 / estimate.resolution_m;
  for (int r = 0; r < canvas.height; ++r) {
    auto* row = out.ptr<std::uint8_t>(r);
    const double y = canvas.CenterY(r);
    for (int col = 0; col < canvas.width; ++col) {
      const double x = canvas.CenterX(col);
      const double ex = to_estimate.x_m + c * x - s * y;
      const double ey = to_estimate.y_m + s * x + c * y;
      const int ec = static_cast<int>(std::floor((ex - estimate.origin.x_m) * inv_res));
      const int from_bottom = static_cast<int>(std::floor((ey - estimate.origin.y_m) * inv_res));
      if (ec < 0 || ec >= estimate.width || from_bottom < 0 || from_bottom >= estimate.height) continue;
      row[col] = Classify(estimate.at(estimate.height - 1 - from_bottom, ec), options);
    }
  }
  return out;
}

/// Distance (cells) from every canvas cell to the nearest occupied cell of `classes`.
cv::Mat DistanceToOccupied(const cv::Mat& classes) {
  cv::Mat not_occupied = classes != kOccupiedCell;
  cv::Mat distance;
  cv::distanceTransform(not_occupied, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  return distance;
}

struct Directed {
  double mean = 0, max = 0, within = 0;
  std::size_t count = 0;
};

Directed DirectedDistances(const cv::Mat& from_classes, const cv::Mat& to_distance, int radius) {
  Directed d;
  double sum = 0;
  std::size_t within = 0;
  for (int r = 0; r < from_classes.rows; ++r) {
    const auto* classes = from_classes.ptr<std::uint8_t>(r);
    const auto* distance = to_distance.ptr<float>(r);
    for (int c = 0; c < from_classes.cols; ++c) {
      if (classes[c] != kOccupiedCell) continue;
      ++d.count;
      sum += distance[c];
      d.max = std::max<double>(d.max, distance[c]);
      within += distance[c] <= radius;
    }
  }
  if (d.count > 0) d.mean = sum / d.count, d.within = static_cast<double>(within) / d.count;
  return d;
}

/// Point-to-point ICP of the estimate's occupied cells onto the reference's, nearest neighbours from
/// a labelled distance transform of the reference, closed-form rigid fit per iteration.
MapTransform RefineWithIcp(const OccupancyGrid& estimate, const OccupancyGrid& reference, MapTransform transform,
                           const MapCompareOptions& options) {
  std::vector<Point2> points;
  for (int r = 0; r < estimate.height; ++r) {
    for (int c = 0; c < estimate.width; ++c) {
      if (Classify(estimate.at(r, c), options) == kOccupiedCell) points.push_back({estimate.CellCenterXM(c), estimate.CellCenterYM(r)});
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

}  // namespace

MapComparison CompareMaps(const OccupancyGrid& estimate, const OccupancyGrid& reference, const MapCompareOptions& options) {
  if (std::abs(estimate.resolution_m - reference.resolution_m) > 0.01 * reference.resolution_m) {
    throw InputError("map-compare: the maps have different cell sizes (" + std::to_string(estimate.resolution_m) +
                     " m and " + std::to_string(reference.resolution_m) + " m); resample one first");
  }
  if (options.match_radius_cells < 0) throw InputError("map-compare: match radius must be >= 0 cells");
  MapComparison result;
  result.transform = options.refine_with_icp ? RefineWithIcp(estimate, reference, options.transform, options) : options.transform;
  const Canvas canvas = MakeCanvas(estimate, reference, result.transform, options.match_radius_cells + 1);
  const cv::Mat ref = RasterReference(reference, canvas, options);
  const cv::Mat est = RasterEstimate(estimate, result.transform, canvas, options);
  const Directed to_reference = DirectedDistances(est, DistanceToOccupied(ref), options.match_radius_cells);
  const Directed to_estimate = DirectedDistances(ref, DistanceToOccupied(est), options.match_radius_cells);
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
  std::size_t both = 0, occ_and = 0, occ_or = 0, free_and = 0, free_or = 0;
  for (int r = 0; r < canvas.height; ++r) {
    const auto* a = est.ptr<std::uint8_t>(r);
    const auto* b = ref.ptr<std::uint8_t>(r);
    for (int c = 0; c < canvas.width; ++c) {
      if (a[c] == kUnknownCell || b[c] == kUnknownCell) continue;
      ++both;
      occ_and += a[c] == kOccupiedCell && b[c] == kOccupiedCell;
      occ_or += a[c] == kOccupiedCell || b[c] == kOccupiedCell;
      free_and += a[c] == kFreeCell && b[c] == kFreeCell;
      free_or += a[c] == kFreeCell || b[c] == kFreeCell;
    }
  }
  result.known_in_both = both;
  result.iou_occupied = occ_or > 0 ? static_cast<double>(occ_and) / occ_or : 0.0;
  result.iou_free = free_or > 0 ? static_cast<double>(free_and) / free_or : 0.0;
  return result;
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
          {"cells", {{"estimate_occupied", estimate_occupied}, {"reference_occupied", reference_occupied},
                     {"known_in_both", known_in_both}}},
          {"transform", {{"x_m", transform.x_m}, {"y_m", transform.y_m}, {"yaw_rad", transform.yaw_rad}}},
          {"specification", {{"occupied_threshold", options.occupied_threshold},
                             {"free_threshold", options.free_threshold},
                             {"match_radius_cells", options.match_radius_cells},
                             {"alignment", options.refine_with_icp ? "icp" : "given"},
                             {"distance", "exact Euclidean distance transform between occupied cells (OpenCV DIST_MASK_PRECISE)"}}}};
}

}  // namespace slamsweep::evaluator
