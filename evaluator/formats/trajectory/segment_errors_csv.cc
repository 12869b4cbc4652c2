#include "evaluator/formats/trajectory/segment_errors_csv.h"

#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

void WriteSegmentErrorsCsv(const std::vector<SegmentErrorRecord>& records, std::ostream& out) {
  out << kSegmentErrorsHeader << '\n';
  for (const SegmentErrorRecord& r : records) {
    out << ShortestText(r.length_m) << ',' << ShortestText(r.start_s) << ',' << ShortestText(r.end_s) << ','
        << ShortestText(r.translation_m) << ',' << ShortestText(r.translation_pct) << ','
        << ShortestText(r.rotation_deg_per_m) << '\n';
  }
}

void WriteSegmentErrorsCsv(const std::vector<SegmentErrorRecord>& records, const std::filesystem::path& path) {
  WriteOutputFile(path, [&](std::ostream& out) { WriteSegmentErrorsCsv(records, out); });
}

std::vector<SegmentErrorRecord> ParseSegmentErrorsCsv(std::string_view content, const std::filesystem::path& source) {
  std::vector<SegmentErrorRecord> records;
  bool header_seen = false;
  ForEachRecord(
      source, content,
      [&](const TextRecord& record) {
        if (!header_seen) {
          std::string header;
          for (std::size_t i = 0; i < record.size(); ++i) {
            if (i > 0) header += ',';
            header += record.Text(i);
          }
          if (header != kSegmentErrorsHeader) {
            record.Fail("expected the header '" + std::string(kSegmentErrorsHeader) + "', got '" + header + "'");
          }
          header_seen = true;
          return;
        }
        if (record.size() != 6) {
          record.Fail("expected 6 fields (" + std::string(kSegmentErrorsHeader) + "), got " +
                      std::to_string(record.size()));
        }
        records.push_back({record.Number(0, "length_m"), record.Number(1, "start_s"), record.Number(2, "end_s"),
                           record.Number(3, "translation_m"), record.Number(4, "translation_pct"),
                           record.Number(5, "rotation_deg_per_m")});
      },
      ",\r", "#");
  if (!header_seen) {
    throw InputError(source.string() + ": expected the header '" + std::string(kSegmentErrorsHeader) + "'");
  }
  return records;
}

std::vector<SegmentErrorRecord> ReadSegmentErrorsCsv(const std::filesystem::path& path) {
  return ParseSegmentErrorsCsv(ReadTextFile(path), path);
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
