#include "tests/report/fake_artwork.h"

#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace slamsweep::report::testing {

namespace {

namespace fs = std::filesystem;

void WritePng(const fs::path& png, int value) {
  cv::Mat image(12, 16, CV_8UC1, cv::Scalar(value));
  if (!cv::imwrite(png.string(), image)) throw std::runtime_error("cannot write " + png.string());
}

std::string Unescape(std::string text) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [entity, plain] : entities) {
    for (std::size_t pos = 0; (pos = text.find(entity, pos)) != std::string::npos; pos += std::string(plain).size()) {
      text.replace(pos, std::string(entity).size(), plain);
    }
  }
  return text;
}

}  // namespace

void FakeArtwork::Plots(const std::vector<PlotRequest>& requests) {
  plots = requests;
  for (const PlotRequest& request : requests) WritePng(request.png, 128);
}

void FakeArtwork::ScatterPlots(const std::vector<ScatterPlotJob>& jobs) {
  scatter_plots = jobs;
  for (const ScatterPlotJob& job : jobs) WritePng(job.png, 64);
}

void FakeArtwork::Figures(const std::vector<FigureJob>& jobs) {
  figures = jobs;
  for (const FigureJob& job : jobs) WritePng(job.png, 90);
}

MapComparisonDrawn FakeArtwork::MapComparison(const MapComparisonJob& job) {
  {
    std::lock_guard lock(map_mutex);
    map_comparisons.push_back(job);
  }
  MapComparisonDrawn drawn;
  drawn.metres_per_pixel = 0.05;
  drawn.window_width_m = 4.0;
  drawn.window_height_m = 3.0;
  if (!job.reference_png.empty()) {
    WritePng(job.reference_png, 150);
    drawn.reference_made = true;
  }
  for (const MapPanelRequest& request : job.panels) {
    MapPanelDrawn& panel = drawn.panels.emplace_back();
    WritePng(request.png, 170);
    panel.made = true;
    if (request.difference_png.empty()) continue;
    WritePng(request.difference_png, 180);
    panel.difference_made = true;
    panel.counts = WallCounts{1, 2, 3};
  }
  return drawn;
}

namespace {

void WriteTinyGif(const fs::path& gif) {
  // The smallest valid GIF89a: one 1x1 frame.
  static const unsigned char kGif[] = {0x47, 0x49, 0x46, 0x38, 0x39, 0x61, 0x01, 0x00, 0x01, 0x00, 0x80,
                                       0x00, 0x00, 0xff, 0xff, 0xff, 0x00, 0x00, 0x00, 0x21, 0xf9, 0x04,
                                       0x01, 0x00, 0x00, 0x00, 0x00, 0x2c, 0x00, 0x00, 0x00, 0x00, 0x01,
                                       0x00, 0x01, 0x00, 0x00, 0x02, 0x02, 0x44, 0x01, 0x00, 0x3b};
  std::ofstream out(gif, std::ios::binary);
  out.write(reinterpret_cast<const char*>(kGif), sizeof kGif);
}

}  // namespace

void FakeArtwork::StagesGif(const std::vector<fs::path>& stage_pngs, const fs::path& gif, const GifSettings&) {
  if (stage_pngs.empty()) throw std::runtime_error("no stages");
  {
    std::lock_guard lock(stages_mutex);
    stages.insert(stages.end(), stage_pngs.begin(), stage_pngs.end());
  }
  WriteTinyGif(gif);
  ++gifs;
}

void FakeArtwork::StagesGifFromAnimation(const fs::path& animation, const fs::path& gif, const GifSettings&) {
  if (!fs::is_regular_file(animation)) throw std::runtime_error("no animation at " + animation.string());
  {
    std::lock_guard lock(stages_mutex);
    animations.push_back(animation);
  }
  WriteTinyGif(gif);
  ++gifs;
}

void FakeArtwork::Thumbnail(const fs::path& map_image, const fs::path& png, int) {
  if (fail_thumbnails) throw std::runtime_error("thumbnail maker broke on " + map_image.filename().string());
  WritePng(png, 200);
  ++thumbnails;
}

void FakeArtwork::TrajectoryOverlay(const fs::path&, const fs::path&, const fs::path& reference_tum,
                                    const fs::path& png, const OverlaySettings&) {
  WritePng(png, 60);
  ++overlays;
  if (!reference_tum.empty()) ++overlays_with_reference;
}

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

std::vector<std::string> BrokenLinks(const fs::path& root, std::size_t* checked) {
  std::vector<std::string> broken;
  std::size_t count = 0;
  const fs::path canonical_root = fs::weakly_canonical(root);
  const std::regex attribute(R"re((?:href|src)="([^"]*)")re");
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".html") continue;
    const std::string html = ReadAll(entry.path());
    for (std::sregex_iterator it(html.begin(), html.end(), attribute), end; it != end; ++it) {
      ++count;
      const std::string link = Unescape((*it)[1].str());
      const std::string where = fs::relative(entry.path(), root).string() + ": " + link;
      if (link.empty() || link.find(':') != std::string::npos || link.front() == '/' || link.find('#') == 0) {
        broken.push_back(where + " (not a relative file link)");
        continue;
      }
      const fs::path target = fs::weakly_canonical(entry.path().parent_path() / link);
      const std::string relative = target.lexically_relative(canonical_root).string();
      if (relative.empty() || relative.starts_with("..")) {
        broken.push_back(where + " (outside the report)");
      } else if (!fs::is_regular_file(target)) {
        broken.push_back(where + " (no such file)");
      }
    }
  }
  if (checked != nullptr) *checked = count;
  return broken;
}

std::vector<std::string> ImageSources(const fs::path& page) {
  std::vector<std::string> sources;
  const std::string html = ReadAll(page);
  const std::regex image(R"re(<img [^>]*src="([^"]*)")re");
  for (std::sregex_iterator it(html.begin(), html.end(), image), end; it != end; ++it) {
    sources.push_back(Unescape((*it)[1].str()));
  }
  return sources;
}

}  // namespace slamsweep::report::testing
