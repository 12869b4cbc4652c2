#include "evaluator/formats/trajectory/tum_format.h"

#include <fmt/format.h>

#include <array>
#include <fstream>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {

namespace {

/// One TUM line read field by field: the slow path, whose checks name what is wrong.
void AddTumRecord(const TextRecord& record, Trajectory& trajectory) {
  record.RequireFields(8, "timestamp tx ty tz qx qy qz qw");
  if (record.size() > 8)
    record.Fail("expected 8 fields (timestamp tx ty tz qx qy qz qw), got " + std::to_string(record.size()));
  const double stamp = record.Number(0, "timestamp");
  Pose pose;
  pose.position = {record.Number(1, "tx"), record.Number(2, "ty"), record.Number(3, "tz")};
  const Eigen::Quaterniond q(record.Number(7, "qw"), record.Number(4, "qx"), record.Number(5, "qy"),
                             record.Number(6, "qz"));
  if (q.norm() < 1e-9) record.Fail("quaternion (qx qy qz qw) has zero norm; expected a rotation");
  pose.orientation = q.normalized();
  try {
    trajectory.Add(stamp, pose);
  } catch (const InputError& error) {
    record.Fail(error.what());
  }
}

}  // namespace

Trajectory ParseTum(std::string_view content, const std::filesystem::path& source) {
  Trajectory trajectory;
  trajectory.Reserve(CountLines(content));
  ForEachNumberLine<8>(
      content,
      [&](const std::array<double, 8>& v, std::string_view line, std::size_t line_number) {
        // Eight finite numbers: the values AddTumRecord would read, without splitting the line.
        const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
        if (q.norm() >= 1e-9) {
          Pose pose;
          pose.position = {v[1], v[2], v[3]};
          pose.orientation = q.normalized();
          try {
            trajectory.Add(v[0], pose);
            return;
          } catch (const InputError&) {
            // AddTumRecord below says which check failed, located at this line.
          }
        }
        AddTumRecord(TextRecord(source, line_number, SplitFields(line, " \t\r")), trajectory);
      },
      [&](std::string_view line, std::size_t line_number) {
        AddTumRecord(TextRecord(source, line_number, SplitFields(line, " \t\r")), trajectory);
      });
  if (trajectory.empty())
    throw InputError(Located(source, 0, "no poses found (expected TUM lines 'timestamp tx ty tz qx qy qz qw')"));
  return trajectory;
}

Trajectory ReadTum(const std::filesystem::path& path) { return ParseTum(ReadTextFileContent(path).text(), path); }

void WriteTum(const Trajectory& trajectory, std::ostream& out) {
  out << "# timestamp tx ty tz qx qy qz qw\n";
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Pose& p = trajectory.poses()[i];
    const Eigen::Quaterniond& q = p.orientation;
    // {} prints the shortest representation that reads back to the same double.
    out << fmt::format("{} {} {} {} {} {} {} {}\n", trajectory.stamps_s()[i], p.position.x(), p.position.y(),
                       p.position.z(), q.x(), q.y(), q.z(), q.w());
  }
}

void WriteTum(const Trajectory& trajectory, const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw InputError(Located(path, 0, "cannot open for writing"));
  WriteTum(trajectory, out);
  if (!out) throw InputError(Located(path, 0, "write failed"));
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
