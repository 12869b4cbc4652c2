#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator {

/// The file formats a sequence is read from.
enum class SequenceFormat {
  kCarmen,  ///< CARMEN text log, plain or gzip (.log, .log.gz, .clf, .gfs)
  kRawlog,  ///< MRPT rawlog (.rawlog), in either of its two forms
  kRosbag,  ///< ROS1 bag (.bag)
};

/// "carmen", "rawlog", "rosbag".
std::string_view SequenceFormatName(SequenceFormat format);
/// Inverse of SequenceFormatName; InputError naming `option` and the accepted values otherwise.
SequenceFormat ParseSequenceFormat(std::string_view text, std::string_view option = "format");

/// Whether this build can read and write MRPT rawlogs (libmrpt-obs was found) and read ROS1 bags.
bool RawlogSupported();
bool RosbagSupported();

struct SequenceReadOptions {
  /// Empty: the reader's default (the file name without its extensions).
  std::string name;
  /// How CARMEN logs are read (relations, max range, stamp policy); its `name` is overridden by `name`.
  CarmenSequenceOptions carmen;
  /// Scan stamps of rawlogs (the CARMEN stamps are in `carmen`).
  StampOptions rawlog_stamps;
  /// ROS bags: topics to read when the bag has several of a kind (empty: the only one; see
  /// RosbagReadOptions). reference_topic: a nav_msgs/Odometry topic with ground truth.
  std::string scan_topic;
  std::string odometry_topic;
  std::string reference_topic;
};

/// The format of `path`: by extension first (.bag; .rawlog[.gz]; .log, .clf, .gfs with optional
/// .gz), then by content (the "#ROSBAG" magic; text whose first record is a CARMEN message;
/// other gzip data is taken for a rawlog). Throws InputError naming the file when it is missing
/// or none of these.
SequenceFormat DetectSequenceFormat(const std::filesystem::path& path);

/// Reads any supported sequence file (see DetectSequenceFormat). A format this build lacks is an
/// InputError saying so ("ROS bag support not built ..."). Other errors as the format's reader.
Sequence ReadSequence(const std::filesystem::path& path, const SequenceReadOptions& options = {});

/// What SLAM programs read.
enum class SequenceWriteFormat {
  kRawlog,  ///< MRPT Actions/SensoryFrames rawlog (WriteRawlog)
  kCarmen,  ///< CARMEN log: ODOM + FLASER, or ROBOTLASER1 when a scan is not a CARMEN front-laser fan
  kTum,     ///< the reference trajectory, or the odometry when there is none
};

/// "rawlog", "carmen", "tum".
std::string_view SequenceWriteFormatName(SequenceWriteFormat format);
/// Inverse of SequenceWriteFormatName; InputError naming `option` and the accepted values otherwise.
SequenceWriteFormat ParseSequenceWriteFormat(std::string_view text, std::string_view option = "--to");

/// The CARMEN log text of a sequence (what WriteSequence writes for kCarmen). Per scan, in order: an
/// ODOM record (odometry pose) and a laser record stamped with the scan's stamp.
///  - FLASER, when every scan has a fan that CARMEN infers from its beam count (FlaserBeamFan) and the
///    sensor sits at the robot origin: x y theta = the reference pose at the scan's stamp when the
///    reference has that stamp for every scan, else the odometry pose; odom = the odometry pose.
///    A "PARAM robot_front_laser_max" states the max range when all scans agree on it.
///  - ROBOTLASER1 otherwise, stating each scan's geometry; its single robot pose is the odometry
///    (what a SLAM program needs), so a reference does not survive this form.
/// Ranges are written as the shortest text of their float value, so they read back bit for bit.
/// ReadCarmenSequence reads the text back to the same scans, odometry and (FLASER) reference.
std::string FormatCarmenSequence(const Sequence& sequence);

/// Writes `sequence` to `path` in `format`. The sequence must be valid (ValidateSequence).
/// Throws InputError naming the path when it cannot be written, or when the build lacks MRPT for kRawlog.
void WriteSequence(const Sequence& sequence, const std::filesystem::path& path, SequenceWriteFormat format);

}  // namespace slamsweep::evaluator
