#include "evaluator/formats/trajectory/kitti_format.h"

#include <cmath>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/output_file.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::string_view kPoseLayout = "r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz";
// Largest deviation of R^T R from identity accepted as rounding in the file.
constexpr double kRotationTolerance = 1e-3;

Pose ParsePoseRecord(const TextRecord& record) {
  record.RequireFields(12, kPoseLayout);
  if (record.size() > 12) {
    record.Fail("expected 12 fields (" + std::string(kPoseLayout) + "), got " + std::to_string(record.size()));
  }
  static constexpr const char* kNames[12] = {"r11", "r12", "r13", "tx",  "r21", "r22",
                                             "r23", "ty",  "r31", "r32", "r33", "tz"};
  Eigen::Matrix<double, 3, 4> matrix;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 4; ++col) {
      const std::size_t index = static_cast<std::size_t>(row * 4 + col);
      matrix(row, col) = record.Number(index, kNames[index]);
    }
  }
  const Eigen::Matrix3d rotation = matrix.leftCols<3>();
  const double orthogonality_error =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality_error > kRotationTolerance || rotation.determinant() <= 0.0) {
    record.Fail("the 3x3 part is not a rotation (|R^T R - I| = " + std::to_string(orthogonality_error) +
                ", det = " + std::to_string(rotation.determinant()) + "); expected an orthonormal R with det +1");
  }
  Pose pose;
  pose.position = matrix.col(3);
  pose.orientation = Eigen::Quaterniond(rotation).normalized();
  return pose;
}

}  // namespace

Trajectory ParseKittiPoses(std::string_view content, const std::filesystem::path& source) {
  Trajectory trajectory;
  ForEachRecord(source, content, [&](const TextRecord& record) {
    const Pose pose = ParsePoseRecord(record);
    trajectory.Add(static_cast<double>(trajectory.size()), pose);
  });
  if (trajectory.empty()) {
    throw InputError(
        Located(source, 0, "no poses found (expected KITTI lines of 12 numbers: " + std::string(kPoseLayout) + ")"));
  }
  return trajectory;
}

std::vector<double> ParseKittiTimes(std::string_view content, const std::filesystem::path& source) {
  std::vector<double> stamps_s;
  ForEachRecord(source, content, [&](const TextRecord& record) {
    if (record.size() != 1) {
      record.Fail("expected 1 field (the time of one pose in seconds), got " + std::to_string(record.size()));
    }
    stamps_s.push_back(record.Number(0, "time"));
  });
  if (stamps_s.empty()) throw InputError(Located(source, 0, "no times found (expected one number per line)"));
  return stamps_s;
}

Trajectory ReadKitti(const std::filesystem::path& poses_path, const std::filesystem::path& times_path) {
  return ParseKitti(ReadTextFile(poses_path), poses_path, times_path);
}

Trajectory ParseKitti(std::string_view poses_content, const std::filesystem::path& poses_path,
                      const std::filesystem::path& times_path) {
  Trajectory by_index = ParseKittiPoses(poses_content, poses_path);
  if (times_path.empty()) return by_index;
  std::vector<double> stamps_s = ParseKittiTimes(ReadTextFile(times_path), times_path);
  if (stamps_s.size() != by_index.size()) {
    throw InputError(poses_path.string() + ": " + std::to_string(by_index.size()) + " poses but times file " +
                     times_path.string() + " has " + std::to_string(stamps_s.size()) +
                     " stamps; expected one stamp per pose line");
  }
  return Trajectory(std::move(stamps_s), by_index.poses());
}

void WriteKittiPoses(const Trajectory& trajectory, std::ostream& out) {
  for (const Pose& pose : trajectory.poses()) {
    const Eigen::Matrix3d rotation = pose.orientation.toRotationMatrix();
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) out << ShortestText(rotation(row, col)) << ' ';
      out << ShortestText(pose.position[row]) << (row < 2 ? ' ' : '\n');
    }
  }
}

void WriteKittiTimes(const Trajectory& trajectory, std::ostream& out) {
  for (double stamp_s : trajectory.stamps_s()) out << ShortestText(stamp_s) << '\n';
}

void WriteKitti(const Trajectory& trajectory, const std::filesystem::path& poses_path,
                const std::filesystem::path& times_path) {
  WriteOutputFile(poses_path, [&](std::ostream& out) { WriteKittiPoses(trajectory, out); });
  if (!times_path.empty()) {
    WriteOutputFile(times_path, [&](std::ostream& out) { WriteKittiTimes(trajectory, out); });
  }
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
