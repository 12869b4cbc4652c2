#include "report/html/paper_files.h"

#include <system_error>

#include "report/html/safe_name.h"
#include "report/html/site_files.h"
#include "report/html/text_outputs.h"

namespace slamsweep::report::inline html {

namespace fs = std::filesystem;

void WritePaperFiles(const SweepModel& model, const ReportLayout& layout, const fs::path& out_dir, SiteData& site) {
  std::error_code error;
  for (const SequenceModel& sequence : model.sequences) {
    for (const AlgorithmRow& row : sequence.rows) {
      if (row.runs.empty()) continue;  // a reference line has no runs and no files
      const fs::path files = out_dir / layout.FilesDir(row.algorithm, sequence.key);
      MakeDirectories(files);
      WriteTextFile(files / "rmse.txt", RmseText(sequence, row));
      WriteTextFile(files / "corners.txt", MapMetricText(sequence, row, "corners"));
      WriteTextFile(files / "occupied_ratio.txt", MapMetricText(sequence, row, "occupied_to_free_unknown"));
      if (row.median_run && IsRegularFileNoFollow(model.runs[*row.median_run].dir / "trajectory.tum")) {
        LinkOrCopy(model.runs[*row.median_run].dir / "trajectory.tum", files / "pose_log.tum", error);
        if (!error) site.pose_logs.insert({row.algorithm, sequence.key});
      }
    }
  }
}

}  // namespace slamsweep::report::inline html
