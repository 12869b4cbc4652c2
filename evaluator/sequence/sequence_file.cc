#include "evaluator/sequence/sequence_file.h"

#include <fmt/format.h>
#include <zlib.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/carmen_log.h"
#include "evaluator/formats/trajectory/output_file.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/sequence/flaser_fan.h"

#ifdef SLAMSWEEP_HAVE_MRPT
#include "evaluator/formats/rawlog/rawlog_reader.h"
#include "evaluator/formats/rawlog/rawlog_writer.h"
#endif
#ifdef SLAMSWEEP_HAVE_ROSBAG
#include "evaluator/formats/rosbag/rosbag_reader.h"
#endif

namespace slamsweep::evaluator {
namespace {

constexpr std::string_view kMrptMissing =
    "MRPT rawlog support not built (install libmrpt-obs-dev and reconfigure slamsweep)";
constexpr std::string_view kRosbagMissing =
    "ROS bag support not built (install librosbag-dev libsensor-msgs-dev libnav-msgs-dev libtf2-msgs-dev "
    "and reconfigure slamsweep)";
/// Beam geometry closer than this to CARMEN's inferred fan is that fan (the fans are computed in double).
constexpr double kFanToleranceRad = 1e-9;
constexpr double kMountToleranceM = 1e-9;

bool EndsWith(const std::string& text, std::string_view suffix) { return text.ends_with(suffix); }

/// Up to `count` bytes of the file's content, inflated when it is gzip.
std::string PeekContent(const std::filesystem::path& path, std::size_t count) {
  struct GzCloser {
    void operator()(gzFile_s* file) const { gzclose(file); }
  };
  std::unique_ptr<gzFile_s, GzCloser> file(gzopen(path.c_str(), "rb"));
  if (!file) throw InputError(Located(path, 0, "cannot open file for reading"));
  std::string content(count, '\0');
  const int read = gzread(file.get(), content.data(), static_cast<unsigned>(count));
  content.resize(read > 0 ? static_cast<std::size_t>(read) : 0);
  return content;
}

bool HasGzipMagic(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 2> magic{};
  in.read(magic.data(), 2);
  return in.gcount() == 2 && static_cast<unsigned char>(magic[0]) == 0x1f &&
         static_cast<unsigned char>(magic[1]) == 0x8b;
}

/// Whether the first record of `text` (after blank and `#` lines) is a CARMEN message.
bool LooksLikeCarmen(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    const std::string_view rest = line.substr(first);
    const std::string_view word = rest.substr(0, rest.find_first_of(" \t\r"));
    for (std::string_view message : {"FLASER", "RLASER", "ROBOTLASER1", "RAWLASER1", "ODOM", "PARAM", "NEFF",
                                     "TRUEPOS", "SYNC"}) {
      if (word == message) return true;
    }
    return false;
  }
  return false;
}

/// The float's shortest decimal text read back as double, so that FormatCarmenRecord (which writes
/// doubles exactly) writes "1.23" for 1.23f instead of its 17-digit double expansion.
double ShortestFloatAsDouble(float value) {
  std::array<char, 32> text{};
  const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
  double result = value;
  if (error == std::errc()) std::from_chars(text.data(), end, result);
  return result;
}

bool IsFlaserFan(const LaserScan& scan) {
  if (scan.BeamCount() < 2) return false;
  const BeamFan fan = FlaserBeamFan(scan.BeamCount());
  const Pose& mount = scan.sensor_pose_on_robot;
  return fan.known_layout && std::abs(fan.angle_min_rad - scan.angle_min_rad) < kFanToleranceRad &&
         std::abs(fan.angle_increment_rad - scan.angle_increment_rad) < kFanToleranceRad &&
         mount.position.norm() < kMountToleranceM && RotationAngleRad(mount.orientation) < kFanToleranceRad;
}

/// The reference poses at the scans' stamps when the reference has every one of them, else nullopt.
std::optional<std::vector<Pose>> ReferenceAtScans(const Sequence& sequence) {
  if (!sequence.reference) return std::nullopt;
  const std::vector<double>& stamps = sequence.reference->stamps_s();
  std::vector<Pose> poses;
  poses.reserve(sequence.scans.size());
  std::size_t j = 0;
  for (const LaserScan& scan : sequence.scans) {
    while (j < stamps.size() && stamps[j] < scan.stamp_s) ++j;
    if (j == stamps.size() || stamps[j] != scan.stamp_s) return std::nullopt;
    poses.push_back(sequence.reference->poses()[j]);
  }
  return poses;
}

std::vector<double> RangesAsWritten(const LaserScan& scan) {
  std::vector<double> ranges;
  ranges.reserve(scan.BeamCount());
  for (float range : scan.ranges_m) ranges.push_back(ShortestFloatAsDouble(range));
  return ranges;
}

void WriteRawlogFile(const Sequence& sequence, const std::filesystem::path& path) {
#ifdef SLAMSWEEP_HAVE_MRPT
  WriteRawlog(sequence, path);
#else
  (void)sequence;
  throw InputError(Located(path, 0, std::string(kMrptMissing)));
#endif
}

}  // namespace

std::string_view SequenceFormatName(SequenceFormat format) {
  switch (format) {
    case SequenceFormat::kCarmen:
      return "carmen";
    case SequenceFormat::kRawlog:
      return "rawlog";
    case SequenceFormat::kRosbag:
      return "rosbag";
  }
  return "unknown";
}

SequenceFormat ParseSequenceFormat(std::string_view text, std::string_view option) {
  for (SequenceFormat format : {SequenceFormat::kCarmen, SequenceFormat::kRawlog, SequenceFormat::kRosbag}) {
    if (text == SequenceFormatName(format)) return format;
  }
  throw InputError(fmt::format("{}: expected carmen, rawlog or rosbag, got '{}'", option, text));
}

bool RawlogSupported() {
#ifdef SLAMSWEEP_HAVE_MRPT
  return true;
#else
  return false;
#endif
}

bool RosbagSupported() {
#ifdef SLAMSWEEP_HAVE_ROSBAG
  return true;
#else
  return false;
#endif
}

SequenceFormat DetectSequenceFormat(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(Located(path, 0, "no such file (expected a sequence: CARMEN log, MRPT rawlog or ROS bag)"));
  }
  std::string name = path.filename().string();
  if (EndsWith(name, ".bag")) return SequenceFormat::kRosbag;
  if (EndsWith(name, ".gz")) name.resize(name.size() - 3);
  if (EndsWith(name, ".rawlog")) return SequenceFormat::kRawlog;
  for (std::string_view suffix : {".log", ".clf", ".gfs"}) {
    if (EndsWith(name, suffix)) return SequenceFormat::kCarmen;
  }
  const std::string head = PeekContent(path, 4096);
  if (head.starts_with("#ROSBAG")) return SequenceFormat::kRosbag;
  if (LooksLikeCarmen(head)) return SequenceFormat::kCarmen;
  if (HasGzipMagic(path)) return SequenceFormat::kRawlog;
  throw InputError(Located(path, 0,
                           "unknown sequence format: expected a CARMEN log (.log, .clf, .gfs, optionally .gz), an "
                           "MRPT rawlog (.rawlog) or a ROS1 bag (.bag)"));
}

Sequence ReadSequence(const std::filesystem::path& path, const SequenceReadOptions& options) {
  switch (DetectSequenceFormat(path)) {
    case SequenceFormat::kCarmen: {
      CarmenSequenceOptions carmen = options.carmen;
      if (!options.name.empty()) carmen.name = options.name;
      return ReadCarmenSequence(path, carmen);
    }
    case SequenceFormat::kRawlog: {
#ifdef SLAMSWEEP_HAVE_MRPT
      RawlogReadOptions rawlog;
      rawlog.name = options.name;
      rawlog.stamps = options.rawlog_stamps;
      return ReadRawlog(path, rawlog);
#else
      throw InputError(Located(path, 0, std::string(kMrptMissing)));
#endif
    }
    case SequenceFormat::kRosbag: {
#ifdef SLAMSWEEP_HAVE_ROSBAG
      RosbagReadOptions rosbag;
      rosbag.name = options.name;
      rosbag.scan_topic = options.scan_topic;
      rosbag.odometry_topic = options.odometry_topic;
      rosbag.reference_topic = options.reference_topic;
      return ReadRosbag(path, rosbag);
#else
      throw InputError(Located(path, 0, std::string(kRosbagMissing)));
#endif
    }
  }
  throw InputError(Located(path, 0, "unknown sequence format"));
}

std::string_view SequenceWriteFormatName(SequenceWriteFormat format) {
  switch (format) {
    case SequenceWriteFormat::kRawlog:
      return "rawlog";
    case SequenceWriteFormat::kCarmen:
      return "carmen";
    case SequenceWriteFormat::kTum:
      return "tum";
  }
  return "unknown";
}

SequenceWriteFormat ParseSequenceWriteFormat(std::string_view text, std::string_view option) {
  for (SequenceWriteFormat format :
       {SequenceWriteFormat::kRawlog, SequenceWriteFormat::kCarmen, SequenceWriteFormat::kTum}) {
    if (text == SequenceWriteFormatName(format)) return format;
  }
  throw InputError(fmt::format("{}: expected rawlog, carmen or tum, got '{}'", option, text));
}

std::string FormatCarmenSequence(const Sequence& sequence) {
  ValidateSequence(sequence);
  bool flaser = true;
  for (const LaserScan& scan : sequence.scans) flaser = flaser && IsFlaserFan(scan);
  const std::optional<std::vector<Pose>> reference = ReferenceAtScans(sequence);

  std::string out = "# " + sequence.name + ", written by slamsweep\n";
  const double max_range_m = sequence.scans.front().range_max_m;
  bool same_max_range = true;
  for (const LaserScan& scan : sequence.scans) same_max_range = same_max_range && scan.range_max_m == max_range_m;
  if (flaser && same_max_range) {
    out += FormatCarmenRecord(CarmenParam{"robot_front_laser_max", ShortestText(max_range_m), 0}) + '\n';
  }
  for (std::size_t i = 0; i < sequence.scans.size(); ++i) {
    const LaserScan& scan = sequence.scans[i];
    const Pose& odometry = sequence.odometry.poses()[i];
    CarmenOdomRecord odom;
    odom.pose = odometry;
    odom.ipc_stamp_s = scan.stamp_s;
    odom.logger_stamp_s = scan.stamp_s;
    out += FormatCarmenRecord(odom) + '\n';

    CarmenLaserRecord laser;
    laser.ranges_m = RangesAsWritten(scan);
    laser.ipc_stamp_s = scan.stamp_s;
    laser.logger_stamp_s = scan.stamp_s;
    if (flaser) {
      laser.type = "FLASER";
      laser.robot_pose = reference ? (*reference)[i] : odometry;
      laser.odom_pose = odometry;
    } else {
      laser.type = "ROBOTLASER1";
      CarmenBeamGeometry geometry;
      geometry.start_angle_rad = scan.angle_min_rad;
      geometry.angular_resolution_rad = scan.angle_increment_rad;
      geometry.fov_rad = scan.angle_increment_rad * static_cast<double>(scan.BeamCount() - 1);
      geometry.max_range_m = scan.range_max_m;
      laser.geometry = geometry;
      // As FLASER: the logged robot pose is the reference when there is one; the odometry is in
      // the ODOM record just written (ROBOTLASER1 has no odometry field).
      laser.robot_pose = reference ? (*reference)[i] : odometry;
      laser.laser_pose = laser.robot_pose * scan.sensor_pose_on_robot;
    }
    out += FormatCarmenRecord(laser) + '\n';
  }
  return out;
}

void WriteSequence(const Sequence& sequence, const std::filesystem::path& path, SequenceWriteFormat format) {
  switch (format) {
    case SequenceWriteFormat::kRawlog:
      WriteRawlogFile(sequence, path);
      return;
    case SequenceWriteFormat::kCarmen: {
      const std::string text = FormatCarmenSequence(sequence);
      WriteOutputFile(path, [&](std::ostream& out) { out << text; });
      return;
    }
    case SequenceWriteFormat::kTum:
      ValidateSequence(sequence);
      WriteTum(sequence.reference ? *sequence.reference : sequence.odometry, path);
      return;
  }
}

}  // namespace slamsweep::evaluator
