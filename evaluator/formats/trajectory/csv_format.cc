#include "evaluator/formats/trajectory/csv_format.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <span>
#include <string>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::array<std::string_view, 4> kSe2Columns = {"timestamp", "x", "y", "theta"};
constexpr std::array<std::string_view, 8> kSe3Columns = {"timestamp", "x", "y", "z", "qx", "qy", "qz", "qw"};
constexpr std::string_view kExpectedHeaders = "'timestamp,x,y,theta' (SE(2)) or 'timestamp,x,y,z,qx,qy,qz,qw' (SE(3))";

/// Where each expected column sits in the file.
struct ColumnLayout {
  bool planar = true;
  std::vector<std::size_t> index;  // index[k] = file column of expected column k
  std::size_t field_count = 0;
};

ColumnLayout ParseHeader(const TextRecord& header) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < header.size(); ++i) names.push_back(AsciiLowercase(header.Text(i)));
  const bool has_theta = std::find(names.begin(), names.end(), "theta") != names.end();
  ColumnLayout layout;
  layout.planar = has_theta;
  layout.field_count = names.size();
  const std::span<const std::string_view> expected =
      has_theta ? std::span<const std::string_view>(kSe2Columns) : std::span<const std::string_view>(kSe3Columns);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(expected.begin(), expected.end(), names[i]) == expected.end()) {
      header.Fail("header column " + std::to_string(i + 1) + " '" + std::string(header.Text(i)) +
                  "' is not one of the " + (has_theta ? "SE(2)" : "SE(3)") + " columns; expected a header " +
                  std::string(kExpectedHeaders));
    }
    if (std::count(names.begin(), names.end(), names[i]) > 1) {
      header.Fail("header column '" + names[i] + "' appears more than once; expected a header " +
                  std::string(kExpectedHeaders));
    }
  }
  for (std::string_view column : expected) {
    const auto found = std::find(names.begin(), names.end(), column);
    if (found == names.end()) {
      header.Fail("header has no column '" + std::string(column) + "'; expected a header " +
                  std::string(kExpectedHeaders));
    }
    layout.index.push_back(static_cast<std::size_t>(found - names.begin()));
  }
  return layout;
}

}  // namespace

Trajectory ParseCsv(std::string_view content, const std::filesystem::path& source) {
  Trajectory trajectory;
  std::optional<ColumnLayout> layout;
  ForEachRecord(
      source, content,
      [&](const TextRecord& record) {
        if (!layout) {
          layout = ParseHeader(record);
          return;
        }
        if (record.size() != layout->field_count) {
          record.Fail("expected " + std::to_string(layout->field_count) +
                      " comma-separated fields like the header, got " + std::to_string(record.size()));
        }
        const std::vector<std::size_t>& at = layout->index;
        Pose pose;
        double stamp_s = 0.0;
        if (layout->planar) {
          stamp_s = record.Number(at[0], "timestamp");
          pose = Pose::Planar(record.Number(at[1], "x"), record.Number(at[2], "y"), record.Number(at[3], "theta"));
        } else {
          stamp_s = record.Number(at[0], "timestamp");
          pose.position = {record.Number(at[1], "x"), record.Number(at[2], "y"), record.Number(at[3], "z")};
          const Eigen::Quaterniond q(record.Number(at[7], "qw"), record.Number(at[4], "qx"), record.Number(at[5], "qy"),
                                     record.Number(at[6], "qz"));
          if (q.norm() < 1e-9) record.Fail("quaternion (qx qy qz qw) has zero norm; expected a rotation");
          pose.orientation = q.normalized();
        }
        trajectory.Add(stamp_s, pose);
      },
      ",");
  if (!layout) throw InputError(Located(source, 0, "empty file: expected a header " + std::string(kExpectedHeaders)));
  if (trajectory.empty()) throw InputError(Located(source, 0, "no poses found after the header"));
  return trajectory;
}

Trajectory ReadCsv(const std::filesystem::path& path) { return ParseCsv(ReadTextFile(path), path); }

void WriteCsv(const Trajectory& trajectory, std::ostream& out) {
  const bool planar = trajectory.IsPlanar(0.0);
  out << (planar ? "timestamp,x,y,theta\n" : "timestamp,x,y,z,qx,qy,qz,qw\n");
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Pose& pose = trajectory.poses()[i];
    out << ShortestText(trajectory.stamps_s()[i]) << ',' << ShortestText(pose.position.x()) << ','
        << ShortestText(pose.position.y()) << ',';
    if (planar) {
      out << ShortestText(pose.Yaw()) << '\n';
    } else {
      const Eigen::Quaterniond& q = pose.orientation;
      out << ShortestText(pose.position.z()) << ',' << ShortestText(q.x()) << ',' << ShortestText(q.y()) << ','
          << ShortestText(q.z()) << ',' << ShortestText(q.w()) << '\n';
    }
  }
}

void WriteCsv(const Trajectory& trajectory, const std::filesystem::path& path) {
  WriteOutputFile(path, [&](std::ostream& out) { WriteCsv(trajectory, out); });
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
