#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/formats/bag/bag_options.h"
#include "evaluator/sequence/carmen_sequence.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence_io {

/// The file formats a sequence is read from.
enum class SequenceFormat {
  kCarmen,   ///< CARMEN text log, plain or gzip (.log, .log.gz, .clf)
  kRawlog,   ///< MRPT rawlog (.rawlog), in either of its two forms
  kRosbag,   ///< ROS 1 bag (.bag)
  kRosbag2,  ///< ROS 2 bag: a rosbag2 folder (metadata.yaml), or a .db3 or .mcap file
};

/// "carmen", "rawlog", "rosbag", "rosbag2".
std::string_view SequenceFormatName(SequenceFormat format);
/// Inverse of SequenceFormatName; InputError naming `option` and the accepted values otherwise.
SequenceFormat ParseSequenceFormat(std::string_view text, std::string_view option = "format");

/// Whether this installation can read and write MRPT rawlogs and read ROS 1 bags: the format's module
/// (evaluator/sequence_io/format_modules.h) was built and loads. Loads it. (ROS 2 bags are always read.)
bool RawlogSupported();
bool RosbagSupported();

struct SequenceReadOptions {
  /// Empty: the reader's default (the file name without its extensions).
  std::string name;
  /// How CARMEN logs are read (relations, max range, stamp policy); its `name` is overridden by `name`.
  CarmenSequenceOptions carmen;
  /// Scan stamps of rawlogs (the CARMEN stamps are in `carmen`).
  StampOptions rawlog_stamps;
  /// ROS 1 and ROS 2 bags: which topics and frames make the sequence (BagChoices).
  BagChoices bag;
};

/// The format of `path`: a folder is a rosbag2 bag (it must hold metadata.yaml); a file by extension
/// first (.bag; .db3, .mcap; .rawlog[.gz]; .log, .clf with optional .gz), then by content (the
/// "#ROSBAG" and MCAP magics; text whose first record is a CARMEN message; other gzip data is taken
/// for a rawlog). Throws InputError naming the file when it is missing or none of these.
SequenceFormat DetectSequenceFormat(const std::filesystem::path& path);

/// The files a sequence at `path` consists of, each checked to exist: the file itself, or a rosbag2
/// folder's metadata.yaml and split files. Throws InputError naming what is missing. For checks
/// before anything is read (the catalog, sweep files).
std::vector<std::filesystem::path> SequenceFiles(const std::filesystem::path& path);

/// Reads any supported sequence file (see DetectSequenceFormat). A format this build lacks is an
/// InputError saying so ("ROS bag support not built ..."). Other errors as the format's reader.
Sequence ReadSequence(const std::filesystem::path& path, const SequenceReadOptions& options = {});

}  // namespace slamsweep::evaluator::inline sequence_io
