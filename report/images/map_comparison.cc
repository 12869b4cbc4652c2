#include "report/images/map_comparison.h"

#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/image_file.h"
#include "evaluator/formats/map/map_file.h"
#include "report/images/map_panels.h"

namespace slamsweep::report::inline images {
namespace {

namespace fs = std::filesystem;
using evaluator::OccupancyGrid;

void WritePanel(const cv::Mat& image, double metres_per_pixel, const fs::path& png) {
  cv::Mat bgr;
  if (image.channels() == 1) {
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  } else {
    bgr = image.clone();
  }
  DrawScaleBar(bgr, metres_per_pixel);
  evaluator::WriteBinaryFile(png, evaluator::EncodePng(bgr));
}

}  // namespace

MapComparisonDrawn WriteMapComparison(const MapComparisonJob& job) {
  MapComparisonDrawn drawn;
  drawn.panels.resize(job.panels.size());
  // Reference maps by file: the panels of a table usually share one.
  std::map<fs::path, std::shared_ptr<const OccupancyGrid>> references;
  const auto reference_of = [&](const fs::path& file) {
    auto& slot = references[file];
    if (!slot) slot = std::make_shared<const OccupancyGrid>(evaluator::ReadMap(file));
    return slot;
  };

  std::optional<WorldWindow> window;
  std::shared_ptr<const OccupancyGrid> table_reference;
  std::string reference_error;
  if (!job.reference_map_file.empty()) {
    try {
      table_reference = reference_of(job.reference_map_file);
      window = KnownExtent(*table_reference, {});
    } catch (const std::exception& error) {
      reference_error = error.what();
    }
  }
  std::vector<std::optional<OccupancyGrid>> maps(job.panels.size());
  for (std::size_t i = 0; i < job.panels.size(); ++i) {
    const MapPanelRequest& request = job.panels[i];
    try {
      OccupancyGrid map = evaluator::ReadMap(request.map_file);
      // Cropped to its known cells on the lattice its scores used (the reference's cells), when it has one.
      double later_resolution_m = map.resolution_m;
      if (!request.reference_map_file.empty() && !request.difference_png.empty()) {
        try {
          later_resolution_m = reference_of(request.reference_map_file)->resolution_m / request.placement.scale;
        } catch (const std::exception& error) {
          drawn.panels[i].difference_note = error.what();
        }
      }
      maps[i] = KnownPart(std::move(map), later_resolution_m);
    } catch (const std::exception& error) {
      drawn.panels[i].note = error.what();
      continue;
    }
    if (table_reference) continue;  // the reference's window
    if (const auto extent = KnownExtent(*maps[i], request.placement))
      window = window ? window->Union(*extent) : *extent;
  }
  if (!window) {
    throw evaluator::InputError(
        "maps compared: no map has a known cell" +
        (reference_error.empty() ? std::string() : " (reference map: " + reference_error + ")"));
  }
  const PanelGeometry panel = ChoosePanelGeometry(*window, job.max_side_px);
  drawn.metres_per_pixel = panel.metres_per_pixel;
  drawn.window_width_m = panel.window.Width();
  drawn.window_height_m = panel.window.Height();

  if (table_reference && !job.reference_png.empty()) {
    WritePanel(RenderMapPanel(*table_reference, {}, panel), panel.metres_per_pixel, job.reference_png);
    drawn.reference_made = true;
  }
  for (std::size_t i = 0; i < job.panels.size(); ++i) {
    if (!maps[i]) continue;
    const MapPanelRequest& request = job.panels[i];
    MapPanelDrawn& out = drawn.panels[i];
    try {
      WritePanel(RenderMapPanel(*maps[i], request.placement, panel), panel.metres_per_pixel, request.png);
      out.made = true;
    } catch (const std::exception& error) {
      out.note = error.what();
      continue;
    }
    if (request.reference_map_file.empty() || request.difference_png.empty() || !out.difference_note.empty()) continue;
    try {
      const WallDifference difference =
          CompareWalls(*maps[i], request.placement, *reference_of(request.reference_map_file), request.match);
      WritePanel(RenderDifferencePanel(difference, panel), panel.metres_per_pixel, request.difference_png);
      out.difference_made = true;
      out.counts = difference.counts;
    } catch (const std::exception& error) {
      out.difference_note = error.what();
    }
  }
  return drawn;
}

}  // namespace slamsweep::report::inline images
