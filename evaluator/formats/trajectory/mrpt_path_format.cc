#include "evaluator/formats/trajectory/mrpt_path_format.h"

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/euler_angles.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/planarity.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

constexpr std::string_view kIcpLayout = "step x y phi";
constexpr std::string_view kRbpfLayout = "step x y z yaw pitch roll timestamp";

std::size_t FieldCount(MrptPathLayout layout) { return layout == MrptPathLayout::kIcpSlam ? 4 : 8; }
std::string_view LayoutText(MrptPathLayout layout) {
  return layout == MrptPathLayout::kIcpSlam ? kIcpLayout : kRbpfLayout;
}

}  // namespace

MrptPath ParseMrptPath(std::string_view content, const std::filesystem::path& source) {
  MrptPath path;
  bool layout_known = false;
  ForEachRecord(
      source, content,
      [&](const TextRecord& record) {
        if (record.Text(0).starts_with('#')) return;
        if (!layout_known) {
          if (record.size() == 4) {
            path.layout = MrptPathLayout::kIcpSlam;
          } else if (record.size() == 8) {
            path.layout = MrptPathLayout::kRbpfSlam;
          } else {
            record.Fail("expected 4 fields (icp-slam: " + std::string(kIcpLayout) + ") or 8 fields (rbpf-slam: " +
                        std::string(kRbpfLayout) + "), got " + std::to_string(record.size()));
          }
          layout_known = true;
        }
        const std::size_t expected = FieldCount(path.layout);
        if (record.size() != expected) {
          record.Fail("expected " + std::to_string(expected) + " fields (" + std::string(LayoutText(path.layout)) +
                      ") like the first line, got " + std::to_string(record.size()));
        }
        const long long step = record.Integer(0, "step");
        if (step < 0) record.Fail("field 1 (step): expected a step index >= 0, got " + std::to_string(step));
        Pose pose;
        if (path.layout == MrptPathLayout::kIcpSlam) {
          pose = Pose::Planar(record.Number(1, "x"), record.Number(2, "y"), record.Number(3, "phi"));
        } else {
          pose.position = {record.Number(1, "x"), record.Number(2, "y"), record.Number(3, "z")};
          pose.orientation = QuaternionFromRollPitchYaw({.roll_rad = record.Number(6, "roll"),
                                                         .pitch_rad = record.Number(5, "pitch"),
                                                         .yaw_rad = record.Number(4, "yaw")});
          path.stamps_s.push_back(record.Number(7, "timestamp"));
        }
        path.steps.push_back(static_cast<std::size_t>(step));
        path.poses.push_back(pose);
        path.lines.push_back(record.line_number());
      },
      " \t\r", "%");
  if (path.poses.empty()) {
    throw InputError(Located(source, 0,
                             "no poses found (expected MRPT log_estimated_path lines '" + std::string(kIcpLayout) +
                                 "' or '" + std::string(kRbpfLayout) + "')"));
  }
  return path;
}

MrptPath ReadMrptPath(const std::filesystem::path& path) { return ParseMrptPath(ReadTextFile(path), path); }

Trajectory StampMrptPath(const MrptPath& path, std::span<const double> step_stamps_s,
                         const std::filesystem::path& source) {
  Trajectory trajectory;
  trajectory.Reserve(path.poses.size());
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const std::size_t step = path.steps[i];
    if (step >= step_stamps_s.size()) {
      throw InputError(Located(source, path.lines[i],
                               "step " + std::to_string(step) + " has no stamp: " +
                                   std::to_string(step_stamps_s.size()) + " step stamps were given (steps 0.." +
                                   std::to_string(step_stamps_s.size()) + " - 1); did the SLAM run read another log?"));
    }
    try {
      trajectory.Add(step_stamps_s[step], path.poses[i]);
    } catch (const InputError& error) {
      throw InputError(Located(source, path.lines[i], error.what()));
    }
  }
  return trajectory;
}

Trajectory ReadMrptPath(const std::filesystem::path& path, std::span<const double> step_stamps_s) {
  return StampMrptPath(ReadMrptPath(path), step_stamps_s, path);
}

Trajectory MrptPathTrajectory(const MrptPath& path) {
  std::vector<double> stamps_s = path.stamps_s;
  if (path.layout == MrptPathLayout::kIcpSlam) {
    stamps_s.clear();
    for (std::size_t step : path.steps) stamps_s.push_back(static_cast<double>(step));
  }
  return Trajectory(std::move(stamps_s), path.poses);
}

void WriteMrptPath(const Trajectory& trajectory, std::ostream& out, MrptPathLayout layout) {
  if (layout == MrptPathLayout::kIcpSlam) RequirePlanar(trajectory, "the icp-slam path layout (step x y phi)");
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const Pose& pose = trajectory.poses()[i];
    out << i << ' ' << ShortestText(pose.position.x()) << ' ' << ShortestText(pose.position.y()) << ' ';
    if (layout == MrptPathLayout::kIcpSlam) {
      out << ShortestText(pose.Yaw()) << '\n';
      continue;
    }
    const RollPitchYaw angles = RollPitchYawFromQuaternion(pose.orientation);
    out << ShortestText(pose.position.z()) << ' ' << ShortestText(angles.yaw_rad) << ' '
        << ShortestText(angles.pitch_rad) << ' ' << ShortestText(angles.roll_rad) << ' '
        << ShortestText(trajectory.stamps_s()[i]) << '\n';
  }
}

void WriteMrptPath(const Trajectory& trajectory, const std::filesystem::path& path, MrptPathLayout layout) {
  WriteOutputFile(path, [&](std::ostream& out) { WriteMrptPath(trajectory, out, layout); });
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
