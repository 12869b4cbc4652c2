#pragma once

#include <filesystem>
#include <ostream>
#include <string_view>
#include <vector>

namespace slamsweep::evaluator::inline formats::inline trajectory {

/// One segment of a segment RPE (evaluator/trajectory_metrics/segment_rpe.h), as a run folder's
/// rpe_segments.csv keeps it: the report pools these over the runs of a group for its boxplots.
struct SegmentErrorRecord {
  double length_m = 0.0;
  double start_s = 0.0;  ///< reference stamps of the segment's first and last pose
  double end_s = 0.0;
  double translation_m = 0.0;
  double translation_pct = 0.0;
  double rotation_deg_per_m = 0.0;
};

/// The header line of the file (without newline).
inline constexpr std::string_view kSegmentErrorsHeader =
    "length_m,start_s,end_s,translation_m,translation_pct,rotation_deg_per_m";

/// The header, then one line per record, numbers in their shortest round-trip form.
void WriteSegmentErrorsCsv(const std::vector<SegmentErrorRecord>& records, std::ostream& out);
void WriteSegmentErrorsCsv(const std::vector<SegmentErrorRecord>& records, const std::filesystem::path& path);

/// Throws InputError "FILE:LINE: ..." for a missing or different header, a line without six fields
/// or a field that is not a finite number.
std::vector<SegmentErrorRecord> ParseSegmentErrorsCsv(std::string_view content, const std::filesystem::path& source);
std::vector<SegmentErrorRecord> ReadSegmentErrorsCsv(const std::filesystem::path& path);

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
