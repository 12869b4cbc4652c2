#pragma once

// Writes ROS1 bags with librosbag (rosbag::Bag) for round-trip tests. Compiled as C++17 like
// evaluator/formats/rosbag/ros1_bag_io.cc (ROS1 message headers are not C++20), so this header
// speaks only in the plain types of evaluator/formats/bag/bag_messages.h.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "evaluator/formats/bag/bag_messages.h"

namespace slamsweep::testing {

class BagTestWriter {
 public:
  /// Creates (truncates) the bag; it is complete when the writer is destroyed.
  explicit BagTestWriter(const std::filesystem::path& path);
  ~BagTestWriter();
  BagTestWriter(const BagTestWriter&) = delete;
  BagTestWriter& operator=(const BagTestWriter&) = delete;

  /// Each message is recorded at its record_s, or at its stamp when record_s is 0.
  void WriteScan(const std::string& topic, const evaluator::BagScan& scan);
  void WriteOdometry(const std::string& topic, const evaluator::BagStampedPose& odometry);
  /// One tf2_msgs/TFMessage holding all the transforms, recorded at the first one's time.
  void WriteTransforms(const std::string& topic, const std::vector<evaluator::BagStampedPose>& transforms);
  /// A std_msgs/String: a type the reader does not read.
  void WriteText(const std::string& topic, double record_s, const std::string& text);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace slamsweep::testing
