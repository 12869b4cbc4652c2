#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "evaluator/core/trajectory.h"
#include "evaluator/formats/bag/bag_messages.h"
#include "evaluator/formats/bag/bag_options.h"
#include "evaluator/formats/rosbag2/bag_metadata.h"
#include "evaluator/formats/rosbag2/rosbag2_storage.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline formats::inline rosbag2 {

/// A ROS 2 bag: a bag folder (metadata.yaml and its split files, sqlite3 or MCAP, compressed per file
/// or per message with zstd as rosbag2 does), or one .db3 or .mcap file alone. Topics are matched by
/// name across the split files. Messages must be CDR ("cdr").
class Rosbag2Bag {
 public:
  /// Opens the bag and every split file. Throws InputError naming the folder or file: a folder
  /// without metadata.yaml, a split file it names that is missing, an unknown storage or compression,
  /// a damaged file.
  explicit Rosbag2Bag(const std::filesystem::path& path);

  const std::filesystem::path& Path() const { return path_; }
  /// The folder's name, or the file's name without its extension.
  std::string Name() const;
  const BagSummary& Summary() const { return summary_; }
  /// Decodes the requested topics of every split file, in file order. Throws InputError naming the
  /// file, topic and message for an unknown encoding or a message that does not decode as its type.
  BagMessages ReadMessages(const BagRequest& request) const;

 private:
  std::filesystem::path path_;
  std::string compression_mode_;
  std::vector<std::unique_ptr<Rosbag2File>> files_;
  BagSummary summary_;
};

/// The files a bag consists of, checked to exist: a lone file, or a folder's metadata.yaml and the
/// split files it names. Throws InputError naming what is missing. Reads only metadata.yaml.
std::vector<std::filesystem::path> Rosbag2Files(const std::filesystem::path& path);

/// A ROS 2 bag as a Sequence (ReadBagSequence, evaluator/formats/bag/bag_sequence.h); the name
/// defaults to Rosbag2Bag::Name().
Sequence ReadRosbag2(const std::filesystem::path& path, const BagReadOptions& options = {});

/// The trajectory `selector` ("TOPIC" or "/tf:PARENT.CHILD") names in a ROS 2 bag (ReadBagTrajectory).
Trajectory ReadRosbag2Trajectory(const std::filesystem::path& path, std::string_view selector,
                                 std::vector<std::string>& warnings);

}  // namespace slamsweep::evaluator::inline formats::inline rosbag2
