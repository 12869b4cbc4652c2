#include "evaluator/formats/trajectory/trajectory_file.h"

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "evaluator/formats/trajectory/csv_format.h"
#include "evaluator/formats/trajectory/kitti_format.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/tum_format.h"

namespace slamsweep::evaluator::inline formats::inline trajectory {
namespace {

/// An option meant for another format is a mistake (a wrong file, or a wrong guess by detection);
/// ignoring it would silently give wrong stamps.
void RejectOptionsForOtherFormats(const std::filesystem::path& path, TrajectoryFormat format,
                                  const TrajectoryReadOptions& options) {
  const std::string read_as = " but the file is read as " + std::string(TrajectoryFormatName(format));
  if (!options.kitti_times_path.empty() && format != TrajectoryFormat::kKitti) {
    throw InputError(Located(
        path, 0,
        "option kitti_times_path (" + options.kitti_times_path.string() + ") applies to KITTI files only," + read_as));
  }
  if (!options.mrpt_step_stamps_s.empty() && format != TrajectoryFormat::kMrptPath) {
    throw InputError(Located(path, 0, "option mrpt_step_stamps_s applies to MRPT path files only," + read_as));
  }
}

}  // namespace

TrajectoryFile ReadTrajectoryFile(const std::filesystem::path& path, TrajectoryFormat format,
                                  const TrajectoryReadOptions& options) {
  if (format == TrajectoryFormat::kCarmen) ValidateCarmenReadOptions(options.carmen);
  const TextFileContent file_content = ReadTextFileContent(path);
  const std::string_view content = file_content.text();
  TrajectoryFile file;
  file.format = format == TrajectoryFormat::kAuto ? DetectTrajectoryFormat(path, content) : format;
  RejectOptionsForOtherFormats(path, file.format, options);
  switch (file.format) {
    case TrajectoryFormat::kTum:
      file.trajectory = ParseTum(content, path);
      break;
    case TrajectoryFormat::kKitti:
      file.trajectory = ParseKitti(content, path, options.kitti_times_path);
      break;
    case TrajectoryFormat::kMrptPath: {
      const MrptPath mrpt = ParseMrptPath(content, path);
      file.trajectory = options.mrpt_step_stamps_s.empty() ? MrptPathTrajectory(mrpt)
                                                           : StampMrptPath(mrpt, options.mrpt_step_stamps_s, path);
      break;
    }
    case TrajectoryFormat::kCarmen: {
      CarmenPoses poses = CarmenPosesFromLog(ParseCarmenLog(content, path), path, options.carmen);
      file.trajectory = std::move(poses.trajectory);
      file.warnings = std::move(poses.warnings);
      break;
    }
    case TrajectoryFormat::kCsv:
      file.trajectory = ParseCsv(content, path);
      break;
    case TrajectoryFormat::kAuto:
      throw InputError(Located(path, 0, "trajectory format detection returned no format"));
  }
  return file;
}

Trajectory ReadTrajectory(const std::filesystem::path& path, TrajectoryFormat format,
                          const TrajectoryReadOptions& options) {
  return ReadTrajectoryFile(path, format, options).trajectory;
}

void WriteTrajectory(const Trajectory& trajectory, const std::filesystem::path& path, TrajectoryFormat format,
                     const TrajectoryWriteOptions& options) {
  if (format == TrajectoryFormat::kAuto) format = FormatForOutputPath(path);
  if (!options.kitti_times_path.empty() && format != TrajectoryFormat::kKitti) {
    throw InputError(Located(path, 0,
                             "option kitti_times_path applies to KITTI files only, but the file is written as " +
                                 std::string(TrajectoryFormatName(format))));
  }
  switch (format) {
    case TrajectoryFormat::kTum:
      WriteTum(trajectory, path);
      return;
    case TrajectoryFormat::kKitti:
      WriteKitti(trajectory, path, options.kitti_times_path);
      return;
    case TrajectoryFormat::kMrptPath:
      WriteMrptPath(trajectory, path, options.mrpt_layout);
      return;
    case TrajectoryFormat::kCarmen:
      WriteCarmenPoses(trajectory, path);
      return;
    case TrajectoryFormat::kCsv:
      WriteCsv(trajectory, path);
      return;
    case TrajectoryFormat::kAuto:
      break;
  }
  throw InputError(Located(path, 0, "no trajectory format chosen for writing"));
}

}  // namespace slamsweep::evaluator::inline formats::inline trajectory
