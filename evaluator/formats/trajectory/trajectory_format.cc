#include "evaluator/formats/trajectory/trajectory_format.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::string_view kTriedFormats =
    "tried: TUM (.tum, or .txt with 8 fields 'timestamp tx ty tz qx qy qz qw'); "
    "KITTI (.kitti, or 12 fields: row-major 3x4 [R|t]); "
    "MRPT path (log_estimated_path.txt, or 4 fields 'step x y phi', or 8 fields "
    "'step x y z yaw pitch roll timestamp'); "
    "CARMEN (.log/.log.gz/.clf, lines 'FLASER ...' or 'ROBOTLASER1 ...'); "
    "CSV (.csv with header 'timestamp,x,y,theta' or 'timestamp,x,y,z,qx,qy,qz,qw'). "
    "Name the format explicitly to skip detection";

// Message names that open a line of a CARMEN log.
constexpr std::array<std::string_view, 14> kCarmenMessages = {
    "FLASER",    "RLASER",    "LASER3",    "LASER4", "ROBOTLASER1", "ROBOTLASER2", "RAWLASER1",
    "RAWLASER2", "RAWLASER3", "RAWLASER4", "ODOM",   "PARAM",       "TRUEPOS",     "NEFF"};

/// The extension that tells the format: ".log" for "x.log.gz", ".csv" for "x.csv".
std::string FormatExtension(const std::filesystem::path& path) {
  std::filesystem::path name = path.filename();
  if (AsciiLowercase(name.extension().string()) == ".gz") name = name.stem();
  return AsciiLowercase(name.extension().string());
}

std::optional<TrajectoryFormat> FormatFromName(const std::filesystem::path& path) {
  if (path.filename() == "log_estimated_path.txt") return TrajectoryFormat::kMrptPath;
  const std::string extension = FormatExtension(path);
  if (extension == ".csv") return TrajectoryFormat::kCsv;
  if (extension == ".log" || extension == ".clf") return TrajectoryFormat::kCarmen;
  if (extension == ".kitti") return TrajectoryFormat::kKitti;
  if (extension == ".tum") return TrajectoryFormat::kTum;
  return std::nullopt;
}

struct FirstDataLine {
  std::size_t line_number = 0;
  std::vector<std::string_view> fields;
};

std::optional<FirstDataLine> FindFirstDataLine(std::string_view content) {
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string_view::npos) end = content.size();
    ++line_number;
    const std::string_view line = content.substr(start, end - start);
    start = end + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#' || line[first] == '%') continue;
    return FirstDataLine{line_number, SplitFields(line, " \t\r")};
  }
  return std::nullopt;
}

std::optional<double> ToNumber(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

bool IsInteger(std::string_view text) {
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

/// TUM lines end in a unit quaternion (files print >= 4 digits); rbpf-slam lines end in angles and a time.
bool EndsWithUnitQuaternion(const std::vector<std::string_view>& fields) {
  double norm_squared = 0.0;
  for (std::size_t i = 4; i < 8; ++i) {
    const std::optional<double> value = ToNumber(fields[i]);
    if (!value) return false;
    norm_squared += *value * *value;
  }
  return std::abs(std::sqrt(norm_squared) - 1.0) < 1e-2;
}

}  // namespace

std::string_view TrajectoryFormatName(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::kAuto:
      return "auto";
    case TrajectoryFormat::kTum:
      return "tum";
    case TrajectoryFormat::kKitti:
      return "kitti";
    case TrajectoryFormat::kMrptPath:
      return "mrpt";
    case TrajectoryFormat::kCarmen:
      return "carmen";
    case TrajectoryFormat::kCsv:
      return "csv";
  }
  return "unknown";
}

std::optional<TrajectoryFormat> ParseTrajectoryFormat(std::string_view name) {
  const std::string lower = AsciiLowercase(name);
  for (TrajectoryFormat format : {TrajectoryFormat::kAuto, TrajectoryFormat::kTum, TrajectoryFormat::kKitti,
                                  TrajectoryFormat::kMrptPath, TrajectoryFormat::kCarmen, TrajectoryFormat::kCsv}) {
    if (lower == TrajectoryFormatName(format)) return format;
  }
  return std::nullopt;
}

TrajectoryFormat DetectTrajectoryFormat(const std::filesystem::path& path, std::string_view content) {
  if (const std::optional<TrajectoryFormat> by_name = FormatFromName(path)) return *by_name;
  const std::optional<FirstDataLine> first = FindFirstDataLine(content);
  if (!first)
    throw InputError(
        Located(path, 0, "no data lines, cannot tell the trajectory format; " + std::string(kTriedFormats)));
  const std::vector<std::string_view>& fields = first->fields;
  if (std::find(kCarmenMessages.begin(), kCarmenMessages.end(), fields[0]) != kCarmenMessages.end()) {
    return TrajectoryFormat::kCarmen;
  }
  if (std::any_of(fields.begin(), fields.end(), [](std::string_view f) { return f.find(',') != f.npos; })) {
    return TrajectoryFormat::kCsv;
  }
  if (fields.size() == 12) return TrajectoryFormat::kKitti;
  if (fields.size() == 4) return TrajectoryFormat::kMrptPath;
  if (fields.size() == 8) {
    if (EndsWithUnitQuaternion(fields)) return TrajectoryFormat::kTum;
    if (IsInteger(fields[0])) return TrajectoryFormat::kMrptPath;
    // The TUM reader would normalise any quaternion and accept, e.g., a relations file
    // (t1 t2 x y z roll pitch yaw) as poses; refuse to guess.
    throw InputError(Located(path, first->line_number,
                             "cannot tell the trajectory format: the first data line has 8 fields but fields 5-8 are "
                             "not a unit quaternion (TUM) and field 1 is not an integer step (MRPT rbpf-slam); a "
                             "relations file? " +
                                 std::string(kTriedFormats)));
  }
  std::string shown(fields[0].substr(0, 20));
  throw InputError(Located(path, first->line_number,
                           "cannot tell the trajectory format: the first data line has " +
                               std::to_string(fields.size()) + " fields (first '" + shown + "'); " +
                               std::string(kTriedFormats)));
}

TrajectoryFormat FormatForOutputPath(const std::filesystem::path& path) {
  if (AsciiLowercase(path.extension().string()) == ".gz") {
    throw InputError(Located(path, 0, "the writers produce plain text, not gzip; drop the .gz from the name"));
  }
  if (const std::optional<TrajectoryFormat> by_name = FormatFromName(path)) return *by_name;
  if (FormatExtension(path) == ".txt") return TrajectoryFormat::kTum;
  throw InputError(Located(path, 0,
                           "cannot tell which trajectory format to write from the name; use .tum/.txt (TUM), .csv, "
                           ".kitti, .log (CARMEN) or log_estimated_path.txt (MRPT), or name the format"));
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
