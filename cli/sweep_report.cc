// The report at the end of `run` and `merge`: the same site `slamsweep report` writes.
#include <algorithm>
#include <thread>

#include "cli/command.h"
#include "report/html/standard_artwork.h"
#include "report/html/write_report.h"

namespace slamsweep::cli {

void WriteSweepReport(const std::filesystem::path& result_dir, const Streams& streams) {
  const std::filesystem::path out_dir = result_dir / "report";
  std::unique_ptr<report::Artwork> artwork = report::MakeStandardArtwork();
  report::ReportOptions options;
  options.artwork = artwork.get();
  options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const report::ReportSummary summary = report::WriteReport(result_dir, out_dir, options);
  streams.out << "report: " << (out_dir / "index.html").string() << " (" << summary.runs << " runs";
  if (summary.images_missing > 0) streams.out << ", " << summary.images_missing << " images not made: see their pages";
  streams.out << ")\n";
}

}  // namespace slamsweep::cli
