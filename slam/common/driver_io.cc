#include "slam/common/driver_io.h"

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence_io/sequence_file.h"

namespace slamsweep::slam {

namespace fs = std::filesystem;
using evaluator::InputError;

evaluator::RobotLog ReadDriverInput(const fs::path& input) {
  evaluator::Sequence sequence = evaluator::ReadSequence(input);
  evaluator::RobotLog robot = evaluator::TakeRobotLog(sequence);
  if (robot.scans.empty()) throw InputError(evaluator::Located(input, 0, "holds no laser scan"));
  evaluator::ValidateRobotLog(robot);
  return robot;
}

DriverOutputs::DriverOutputs(fs::path directory, std::size_t scan_count, int stage_count)
    : directory_(std::move(directory)), scan_count_(scan_count), stage_count_(stage_count) {
  std::error_code error;
  fs::create_directories(directory_ / "stages", error);
  if (error) throw InputError(evaluator::Located(directory_, 0, "cannot create output folder: " + error.message()));
  trajectory_.Reserve(scan_count);
}

void DriverOutputs::AddPose(std::size_t scan_index, double stamp_s, const evaluator::Pose& pose) {
  if (scan_index != trajectory_.size()) {
    throw std::logic_error(fmt::format("pose for scan {} added after {} poses", scan_index, trajectory_.size()));
  }
  trajectory_.Add(stamp_s, pose);
}

void DriverOutputs::ReplaceTrajectory(evaluator::Trajectory trajectory) {
  if (trajectory.size() != trajectory_.size() || trajectory.stamps_s() != trajectory_.stamps_s()) {
    throw std::logic_error(fmt::format("replacement trajectory has {} poses for {} scans, or other stamps",
                                       trajectory.size(), trajectory_.size()));
  }
  trajectory_ = std::move(trajectory);
}

bool DriverOutputs::StageDue(std::size_t scan_index) const {
  if (stage_count_ <= 0 || scan_count_ == 0) return false;
  const std::size_t stages = std::min<std::size_t>(static_cast<std::size_t>(stage_count_), scan_count_);
  // Stage k (1..stages) follows scan ceil(k * n / stages) - 1: evenly spread, the last at the last scan.
  const std::size_t k = (scan_index + 1) * stages / scan_count_;
  return k >= 1 && (k * scan_count_ + stages - 1) / stages - 1 == scan_index;
}

void DriverOutputs::WriteStage(std::size_t scan_index, const evaluator::OccupancyGrid& map) {
  evaluator::WriteMapServer(map, directory_ / "stages" / fmt::format("stage-{:06}.yaml", scan_index));
  WriteTrajectory();
}

void DriverOutputs::WriteFinal(const evaluator::OccupancyGrid& map) {
  evaluator::MapWriteOptions options;
  options.mode = evaluator::MapWriteOptions::Mode::kScale;
  evaluator::WriteMapServer(map, directory_ / "map.yaml", options);
  WriteTrajectory();
}

void DriverOutputs::WriteTrajectory() const { evaluator::WriteTum(trajectory_, directory_ / "trajectory.tum"); }

}  // namespace slamsweep::slam
