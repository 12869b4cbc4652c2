#include "evaluator/sequence_io/sequence_codec.h"

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace slamsweep::evaluator::inline sequence_io {
namespace {

constexpr std::size_t kPoseBytes = 7 * sizeof(double);

class Writer {
 public:
  explicit Writer(std::size_t expected_bytes) { out_.reserve(expected_bytes); }

  template <typename T>
  void Plain(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void Count(std::size_t count) { Plain(static_cast<std::uint64_t>(count)); }
  void Flag(bool set) { Plain(static_cast<std::uint8_t>(set ? 1 : 0)); }
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
    const double fields[7] = {pose.position.x(),    pose.position.y(),    pose.position.z(),   pose.orientation.w(),
                              pose.orientation.x(), pose.orientation.y(), pose.orientation.z()};
    out_.append(reinterpret_cast<const char*>(fields), sizeof fields);
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
  bool Flag() {
    const auto flag = Plain<std::uint8_t>();
    if (flag > 1) Fail();
    return flag == 1;
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
    double fields[7];
    std::memcpy(fields, Take(sizeof fields), sizeof fields);
    evaluator::Pose pose;
    pose.position = Eigen::Vector3d(fields[0], fields[1], fields[2]);
    pose.orientation.w() = fields[3];
    pose.orientation.x() = fields[4];
    pose.orientation.y() = fields[5];
    pose.orientation.z() = fields[6];
    return pose;
  }
  evaluator::Trajectory Trajectory() {
    std::vector<double> stamps = Array<double>();
    if (stamps.size() > (bytes_.size() - at_) / kPoseBytes) Fail();
    std::vector<evaluator::Pose> poses;
    poses.reserve(stamps.size());
    for (std::size_t i = 0; i < stamps.size(); ++i) poses.push_back(Pose());
    return evaluator::Trajectory(std::move(stamps), std::move(poses));
  }
  void ExpectEnd() const {
    if (at_ != bytes_.size()) Fail();
  }
  [[noreturn]] static void Fail() {
    throw DamagedSequenceBytes("sequence bytes are damaged (their sizes do not add up)");
  }

 private:
  const char* Take(std::size_t size) {
    if (size > bytes_.size() - at_) Fail();
    const char* start = bytes_.data() + at_;
    at_ += size;
    return start;
  }

  std::string_view bytes_;
  std::size_t at_ = 0;
};

/// Field by field: a struct's padding would make equal facts differ in bytes.
void PutStampFacts(Writer& out, const StampFacts& facts) {
  out.Plain(static_cast<std::int32_t>(facts.outcome));
  out.Count(facts.records);
  out.Count(facts.steps_back);
  out.Count(facts.duplicates);
  out.Plain(facts.largest_step_back_s);
  out.Count(facts.changed);
  out.Plain(facts.largest_change_s);
  out.Flag(facts.order_check.has_value());
  if (facts.order_check) {
    const RecordOrderCheck& check = *facts.order_check;
    for (const std::size_t count : {check.steps, check.scans_closer_in_file_order, check.scans_closer_in_stamp_order,
                                    check.odometry_shorter_in_file_order, check.odometry_shorter_in_stamp_order}) {
      out.Count(count);
    }
  }
}

StampFacts GetStampFacts(Reader& in) {
  StampFacts facts;
  const auto outcome = in.Plain<std::int32_t>();
  if (outcome < static_cast<std::int32_t>(StampOutcome::kRecorded) ||
      outcome > static_cast<std::int32_t>(StampOutcome::kRecordOrder)) {
    Reader::Fail();
  }
  facts.outcome = static_cast<StampOutcome>(outcome);
  facts.records = in.Count(0);
  facts.steps_back = in.Count(0);
  facts.duplicates = in.Count(0);
  facts.largest_step_back_s = in.Plain<double>();
  facts.changed = in.Count(0);
  facts.largest_change_s = in.Plain<double>();
  if (in.Flag()) {
    RecordOrderCheck check;
    for (std::size_t* count : {&check.steps, &check.scans_closer_in_file_order, &check.scans_closer_in_stamp_order,
                               &check.odometry_shorter_in_file_order, &check.odometry_shorter_in_stamp_order}) {
      *count = in.Count(0);
    }
    facts.order_check = check;
  }
  return facts;
}

/// Roughly the bytes EncodeSequence writes, so that the output is allocated once.
std::size_t ExpectedBytes(const Sequence& sequence) {
  std::size_t bytes = 4096;
  for (const LaserScan& scan : sequence.scans) bytes += 13 * sizeof(double) + scan.ranges_m.size() * sizeof(float);
  bytes += (sequence.odometry.size() + sequence.odometry_readings.size()) * 8 * sizeof(double);
  if (sequence.reference) bytes += sequence.reference->size() * 8 * sizeof(double);
  if (sequence.relations) bytes += sequence.relations->size() * 9 * sizeof(double);
  if (sequence.reference_map) bytes += sequence.reference_map->cells.size() * sizeof(float);
  return bytes;
}

}  // namespace

std::string EncodeSequence(const Sequence& sequence) {
  Writer out(ExpectedBytes(sequence));
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
  out.Flag(sequence.reference.has_value());
  if (sequence.reference) out.Trajectory(*sequence.reference);
  out.Flag(sequence.relations.has_value());
  if (sequence.relations) {
    out.Count(sequence.relations->size());
    for (const Relation& relation : *sequence.relations) {
      out.Plain(relation.t1_s);
      out.Plain(relation.t2_s);
      out.Pose(relation.delta);
    }
  }
  out.Count(sequence.relations_outside_log);
  out.Flag(sequence.reference_map.has_value());
  if (sequence.reference_map) {
    const OccupancyGrid& map = *sequence.reference_map;
    out.Plain(map.width);
    out.Plain(map.height);
    out.Plain(map.resolution_m);
    out.Plain(map.origin.x_m);
    out.Plain(map.origin.y_m);
    out.Plain(map.origin.yaw_rad);
    out.Array(map.cells);
  }
  for (const std::string* text : {&sequence.provenance.source, &sequence.provenance.citation,
                                  &sequence.provenance.licence_note, &sequence.provenance.notes}) {
    out.Text(*text);
  }
  out.Count(sequence.warnings.size());
  for (const std::string& warning : sequence.warnings) out.Text(warning);
  out.Flag(sequence.stamp_facts.has_value());
  if (sequence.stamp_facts) PutStampFacts(out, *sequence.stamp_facts);
  return out.Take();
}

Sequence DecodeSequence(std::string_view bytes) {
  Reader in(bytes);
  Sequence sequence;
  sequence.name = in.Text();
  // A scan takes at least its fixed fields.
  sequence.scans.resize(in.Count(5 * sizeof(double) + sizeof(std::uint64_t) + kPoseBytes));
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
  if (in.Flag()) sequence.reference = in.Trajectory();
  if (in.Flag()) {
    Relations relations(in.Count(2 * sizeof(double) + kPoseBytes));
    for (Relation& relation : relations) {
      relation.t1_s = in.Plain<double>();
      relation.t2_s = in.Plain<double>();
      relation.delta = in.Pose();
    }
    sequence.relations = std::move(relations);
  }
  sequence.relations_outside_log = in.Count(0);
  if (in.Flag()) {
    OccupancyGrid map;
    map.width = in.Plain<int>();
    map.height = in.Plain<int>();
    map.resolution_m = in.Plain<double>();
    map.origin.x_m = in.Plain<double>();
    map.origin.y_m = in.Plain<double>();
    map.origin.yaw_rad = in.Plain<double>();
    map.cells = in.Array<float>();
    sequence.reference_map = std::move(map);
  }
  for (std::string* text : {&sequence.provenance.source, &sequence.provenance.citation,
                            &sequence.provenance.licence_note, &sequence.provenance.notes}) {
    *text = in.Text();
  }
  sequence.warnings.resize(in.Count(sizeof(std::uint64_t)));
  for (std::string& warning : sequence.warnings) warning = in.Text();
  if (in.Flag()) sequence.stamp_facts = GetStampFacts(in);
  in.ExpectEnd();
  return sequence;
}

}  // namespace slamsweep::evaluator::inline sequence_io
