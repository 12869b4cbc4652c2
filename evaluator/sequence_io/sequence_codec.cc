#include "evaluator/sequence_io/sequence_codec.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace slamsweep::evaluator::inline sequence_io {
namespace {

class Writer {
 public:
  template <typename T>
  void Plain(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void Count(std::size_t count) { Plain(static_cast<std::uint64_t>(count)); }
  void Text(const std::string& text) {
    Count(text.size());
    out_ += text;
  }
  template <typename T>
  void Array(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    Count(values.size());
    if (!values.empty()) out_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void Pose(const evaluator::Pose& pose) {
    Plain(pose.position.x());
    Plain(pose.position.y());
    Plain(pose.position.z());
    Plain(pose.orientation.w());
    Plain(pose.orientation.x());
    Plain(pose.orientation.y());
    Plain(pose.orientation.z());
  }
  void Trajectory(const evaluator::Trajectory& trajectory) {
    Array(trajectory.stamps_s());
    for (const evaluator::Pose& pose : trajectory.poses()) Pose(pose);
  }
  std::string Take() { return std::move(out_); }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}

  template <typename T>
  T Plain() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, Take(sizeof(T)), sizeof(T));
    return value;
  }
  /// A count of items of `item_bytes` each, checked against the bytes left before anything is allocated.
  std::size_t Count(std::size_t item_bytes) {
    const auto count = Plain<std::uint64_t>();
    if (item_bytes > 0 && count > (bytes_.size() - at_) / item_bytes) Fail();
    return static_cast<std::size_t>(count);
  }
  std::string Text() {
    const std::size_t size = Count(1);
    return std::string(Take(size), size);
  }
  template <typename T>
  std::vector<T> Array() {
    const std::size_t count = Count(sizeof(T));
    std::vector<T> values(count);
    // An empty vector's data() may be null, and memcpy with a null pointer is undefined even for 0 bytes.
    if (count > 0) std::memcpy(values.data(), Take(count * sizeof(T)), count * sizeof(T));
    return values;
  }
  evaluator::Pose Pose() {
    evaluator::Pose pose;
    pose.position.x() = Plain<double>();
    pose.position.y() = Plain<double>();
    pose.position.z() = Plain<double>();
    pose.orientation.w() = Plain<double>();
    pose.orientation.x() = Plain<double>();
    pose.orientation.y() = Plain<double>();
    pose.orientation.z() = Plain<double>();
    return pose;
  }
  evaluator::Trajectory Trajectory() {
    std::vector<double> stamps = Array<double>();
    if (stamps.size() > (bytes_.size() - at_) / (7 * sizeof(double))) Fail();
    std::vector<evaluator::Pose> poses;
    poses.reserve(stamps.size());
    for (std::size_t i = 0; i < stamps.size(); ++i) poses.push_back(Pose());
    return evaluator::Trajectory(std::move(stamps), std::move(poses));
  }
  void ExpectEnd() const {
    if (at_ != bytes_.size()) Fail();
  }

 private:
  const char* Take(std::size_t size) {
    if (size > bytes_.size() - at_) Fail();
    const char* start = bytes_.data() + at_;
    at_ += size;
    return start;
  }
  [[noreturn]] static void Fail() { throw std::runtime_error("a sequence handed over by a reader process is damaged"); }

  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string EncodeSequence(const Sequence& sequence) {
  Writer out;
  out.Text(sequence.name);
  out.Count(sequence.scans.size());
  for (const LaserScan& scan : sequence.scans) {
    out.Plain(scan.stamp_s);
    out.Array(scan.ranges_m);
    out.Plain(scan.angle_min_rad);
    out.Plain(scan.angle_increment_rad);
    out.Plain(scan.range_min_m);
    out.Plain(scan.range_max_m);
    out.Pose(scan.sensor_pose_on_robot);
  }
  out.Trajectory(sequence.odometry);
  out.Trajectory(sequence.odometry_readings);
  out.Plain(static_cast<std::uint8_t>(sequence.reference.has_value()));
  if (sequence.reference) out.Trajectory(*sequence.reference);
  out.Plain(static_cast<std::uint8_t>(sequence.relations.has_value()));
  if (sequence.relations) {
    out.Count(sequence.relations->size());
    for (const Relation& relation : *sequence.relations) {
      out.Plain(relation.t1_s);
      out.Plain(relation.t2_s);
      out.Pose(relation.delta);
    }
  }
  out.Plain(static_cast<std::uint8_t>(sequence.reference_map.has_value()));
  if (sequence.reference_map) {
    const OccupancyGrid& map = *sequence.reference_map;
    out.Plain(map.width);
    out.Plain(map.height);
    out.Plain(map.resolution_m);
    out.Plain(map.origin);
    out.Array(map.cells);
  }
  for (const std::string* text : {&sequence.provenance.source, &sequence.provenance.citation,
                                  &sequence.provenance.licence_note, &sequence.provenance.notes}) {
    out.Text(*text);
  }
  out.Count(sequence.warnings.size());
  for (const std::string& warning : sequence.warnings) out.Text(warning);
  return out.Take();
}

Sequence DecodeSequence(std::string_view bytes) {
  Reader in(bytes);
  Sequence sequence;
  sequence.name = in.Text();
  // A scan takes at least its fixed fields.
  sequence.scans.resize(in.Count(5 * sizeof(double) + sizeof(std::uint64_t)));
  for (LaserScan& scan : sequence.scans) {
    scan.stamp_s = in.Plain<double>();
    scan.ranges_m = in.Array<float>();
    scan.angle_min_rad = in.Plain<double>();
    scan.angle_increment_rad = in.Plain<double>();
    scan.range_min_m = in.Plain<double>();
    scan.range_max_m = in.Plain<double>();
    scan.sensor_pose_on_robot = in.Pose();
  }
  sequence.odometry = in.Trajectory();
  sequence.odometry_readings = in.Trajectory();
  if (in.Plain<std::uint8_t>() != 0) sequence.reference = in.Trajectory();
  if (in.Plain<std::uint8_t>() != 0) {
    Relations relations(in.Count(9 * sizeof(double)));
    for (Relation& relation : relations) {
      relation.t1_s = in.Plain<double>();
      relation.t2_s = in.Plain<double>();
      relation.delta = in.Pose();
    }
    sequence.relations = std::move(relations);
  }
  if (in.Plain<std::uint8_t>() != 0) {
    OccupancyGrid map;
    map.width = in.Plain<int>();
    map.height = in.Plain<int>();
    map.resolution_m = in.Plain<double>();
    map.origin = in.Plain<GridOrigin>();
    map.cells = in.Array<float>();
    sequence.reference_map = std::move(map);
  }
  for (std::string* text : {&sequence.provenance.source, &sequence.provenance.citation,
                            &sequence.provenance.licence_note, &sequence.provenance.notes}) {
    *text = in.Text();
  }
  sequence.warnings.resize(in.Count(sizeof(std::uint64_t)));
  for (std::string& warning : sequence.warnings) warning = in.Text();
  in.ExpectEnd();
  return sequence;
}

}  // namespace slamsweep::evaluator::inline sequence_io
