#pragma once

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "report/html/artwork.h"

namespace slamsweep::report::testing {

/// Writes tiny but valid images (PNG by OpenCV, a 1x1 GIF) instead of drawing, and counts the
/// calls; `fail_thumbnails` makes every thumbnail throw, to test that a failed image is shown as such.
class FakeArtwork : public Artwork {
 public:
  void Plots(const std::vector<PlotRequest>& plots) override;
  void ScatterPlots(const std::vector<ScatterPlotJob>& plots) override;
  void Figures(const std::vector<FigureJob>& figures) override;
  /// Tiny PNGs for every panel, difference and the reference; counts 1, 2, 3; 0.05 m per pixel.
  MapComparisonDrawn MapComparison(const MapComparisonJob& job) override;
  void StagesGif(const std::vector<std::filesystem::path>& stage_pngs, const std::filesystem::path& gif,
                 const GifSettings& settings) override;
  void StagesGifFromAnimation(const std::filesystem::path& animation, const std::filesystem::path& gif,
                              const GifSettings& settings) override;
  void Thumbnail(const std::filesystem::path& map_image, const std::filesystem::path& png, int max_side_px) override;
  void TrajectoryOverlay(const std::filesystem::path& map_yaml, const std::filesystem::path& estimate_tum,
                         const std::filesystem::path& reference_tum, const std::filesystem::path& png,
                         const OverlaySettings& settings) override;

  bool fail_thumbnails = false;
  std::vector<PlotRequest> plots;             ///< written by Plots (called once, from one thread)
  std::vector<ScatterPlotJob> scatter_plots;  ///< written by ScatterPlots (called once, from one thread)
  std::vector<FigureJob> figures;             ///< written by Figures (called once, from one thread)
  std::mutex map_mutex;
  std::vector<MapComparisonJob> map_comparisons;  ///< every job given to MapComparison
  std::atomic<int> gifs{0};
  std::mutex stages_mutex;
  std::vector<std::filesystem::path> stages;      ///< every stage image given to StagesGif
  std::vector<std::filesystem::path> animations;  ///< every animation given to StagesGifFromAnimation
  std::atomic<int> thumbnails{0};
  std::atomic<int> overlays{0};
  std::atomic<int> overlays_with_reference{0};
};

/// Every href/src of every .html file under `root` that does not resolve to a file inside
/// `root` (absolute URLs, data: URIs and escapes from the folder count as broken), as
/// "page: link" lines. Also returns the number of links checked through `checked`.
std::vector<std::string> BrokenLinks(const std::filesystem::path& root, std::size_t* checked = nullptr);

/// The src attributes of the <img> tags of one page, unescaped, in order.
std::vector<std::string> ImageSources(const std::filesystem::path& page);

/// The whole content of a file.
std::string ReadAll(const std::filesystem::path& path);

}  // namespace slamsweep::report::testing
