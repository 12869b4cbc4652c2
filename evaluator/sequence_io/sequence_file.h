#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence_io {

/// The file formats a sequence is read from.
enum class SequenceFormat {
  kCarmen,  ///< CARMEN text log, plain or gzip (.log, .log.gz, .clf)
  kRawlog,  ///< MRPT rawlog (.rawlog), in either of its two forms
  kRosbag,  ///< ROS1 bag (.bag)
};

/// "carmen", "rawlog", "rosbag".
std::string_view SequenceFormatName(SequenceFormat format);
/// Inverse of SequenceFormatName; InputError naming `option` and the accepted values otherwise.
SequenceFormat ParseSequenceFormat(std::string_view text, std::string_view option = "format");

/// Whether this installation can read and write MRPT rawlogs and read ROS1 bags: the format's module
/// (evaluator/sequence_io/format_modules.h) was built and loads. Loads it.
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

/// The format of `path`: by extension first (.bag; .rawlog[.gz]; .log, .clf with optional
/// .gz), then by content (the "#ROSBAG" magic; text whose first record is a CARMEN message;
/// other gzip data is taken for a rawlog). Throws InputError naming the file when it is missing
/// or none of these.
SequenceFormat DetectSequenceFormat(const std::filesystem::path& path);

/// Reads any supported sequence file (see DetectSequenceFormat). A format this build lacks is an
/// InputError saying so ("ROS bag support not built ..."). Other errors as the format's reader.
Sequence ReadSequence(const std::filesystem::path& path, const SequenceReadOptions& options = {});

}  // namespace slamsweep::evaluator::inline sequence_io
