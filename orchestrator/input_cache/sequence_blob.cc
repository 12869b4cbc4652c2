#include "orchestrator/input_cache/sequence_blob.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline input_cache {
namespace {

namespace ev = slamsweep::evaluator;

class Writer {
 public:
  template <typename T>
  void Put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* bytes = reinterpret_cast<const char*>(&value);
    out_.append(bytes, sizeof value);
  }
  void Count(std::size_t count) { Put<std::uint64_t>(count); }
  void Text(const std::string& text) {
    Count(text.size());
    out_.append(text);
  }
  void Floats(const std::vector<float>& values) {
    Count(values.size());
    out_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
  }
  void PoseOf(const ev::Pose& pose) {
    for (const double v : {pose.position.x(), pose.position.y(), pose.position.z(), pose.orientation.w(),
                           pose.orientation.x(), pose.orientation.y(), pose.orientation.z()}) {
      Put(v);
    }
  }
  void TrajectoryOf(const ev::Trajectory& trajectory) {
    Count(trajectory.size());
    for (std::size_t i = 0; i < trajectory.size(); ++i) {
      Put(trajectory.stamps_s()[i]);
      PoseOf(trajectory.poses()[i]);
    }
  }
  std::string Take() { return std::move(out_); }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}

  template <typename T>
  T Get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, Take(sizeof value), sizeof value);
    return value;
  }
  /// A count of items of `item_bytes` each, checked against what is left.
  std::size_t Count(std::size_t item_bytes) {
    const auto count = Get<std::uint64_t>();
    if (item_bytes > 0 && count > (bytes_.size() - at_) / item_bytes) Damaged();
    return static_cast<std::size_t>(count);
  }
  std::string Text() {
    const std::size_t size = Count(1);
    return std::string(Take(size), size);
  }
  std::vector<float> Floats() {
    std::vector<float> values(Count(sizeof(float)));
    std::memcpy(values.data(), Take(values.size() * sizeof(float)), values.size() * sizeof(float));
    return values;
  }
  ev::Pose PoseOf() {
    ev::Pose pose;
    const double x = Get<double>();
    const double y = Get<double>();
    const double z = Get<double>();
    pose.position = Eigen::Vector3d(x, y, z);
    const double qw = Get<double>();
    const double qx = Get<double>();
    const double qy = Get<double>();
    const double qz = Get<double>();
    pose.orientation = Eigen::Quaterniond(qw, qx, qy, qz);
    return pose;
  }
  ev::Trajectory TrajectoryOf() {
    const std::size_t count = Count(8 * sizeof(double));
    std::vector<double> stamps;
    std::vector<ev::Pose> poses;
    stamps.reserve(count);
    poses.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      stamps.push_back(Get<double>());
      poses.push_back(PoseOf());
    }
    return ev::Trajectory(std::move(stamps), std::move(poses));
  }
  void End() const {
    if (at_ != bytes_.size()) Damaged();
  }

 private:
  const char* Take(std::size_t size) {
    if (size > bytes_.size() - at_) Damaged();
    const char* here = bytes_.data() + at_;
    at_ += size;
    return here;
  }
  [[noreturn]] static void Damaged() { throw ev::InputError("prepared sequence: damaged (its sizes do not add up)"); }

  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string EncodeSequence(const ev::Sequence& sequence) {
  Writer out;
  out.Text(sequence.name);
  out.Count(sequence.warnings.size());
  for (const std::string& warning : sequence.warnings) out.Text(warning);
  out.Count(sequence.scans.size());
  for (const ev::LaserScan& scan : sequence.scans) {
    out.Put(scan.stamp_s);
    out.Put(scan.angle_min_rad);
    out.Put(scan.angle_increment_rad);
    out.Put(scan.range_min_m);
    out.Put(scan.range_max_m);
    out.PoseOf(scan.sensor_pose_on_robot);
    out.Floats(scan.ranges_m);
  }
  out.TrajectoryOf(sequence.odometry);
  out.TrajectoryOf(sequence.odometry_readings);
  out.Put<std::uint8_t>(sequence.reference ? 1 : 0);
  if (sequence.reference) out.TrajectoryOf(*sequence.reference);
  out.Put<std::uint8_t>(sequence.relations ? 1 : 0);
  if (sequence.relations) {
    out.Count(sequence.relations->size());
    for (const ev::Relation& relation : *sequence.relations) {
      out.Put(relation.t1_s);
      out.Put(relation.t2_s);
      out.PoseOf(relation.delta);
    }
  }
  out.Count(sequence.relations_outside_log);
  out.Put<std::uint8_t>(sequence.stamp_facts ? 1 : 0);
  if (sequence.stamp_facts) {
    // Field by field: a struct's padding would make equal sequences differ in bytes.
    const ev::StampFacts& facts = *sequence.stamp_facts;
    out.Put(static_cast<std::int32_t>(facts.outcome));
    out.Count(facts.records);
    out.Count(facts.steps_back);
    out.Count(facts.duplicates);
    out.Put(facts.largest_step_back_s);
    out.Count(facts.changed);
    out.Put(facts.largest_change_s);
    out.Put<std::uint8_t>(facts.order_check ? 1 : 0);
    if (facts.order_check) {
      const ev::RecordOrderCheck& check = *facts.order_check;
      for (const std::size_t count : {check.steps, check.scans_closer_in_file_order, check.scans_closer_in_stamp_order,
                                      check.odometry_shorter_in_file_order, check.odometry_shorter_in_stamp_order}) {
        out.Count(count);
      }
    }
  }
  return out.Take();
}

ev::Sequence DecodeSequence(std::string_view bytes) {
  Reader in(bytes);
  ev::Sequence sequence;
  sequence.name = in.Text();
  const std::size_t warnings = in.Count(sizeof(std::uint64_t));
  for (std::size_t i = 0; i < warnings; ++i) sequence.warnings.push_back(in.Text());
  const std::size_t scans = in.Count(12 * sizeof(double) + sizeof(std::uint64_t));
  sequence.scans.resize(scans);
  for (ev::LaserScan& scan : sequence.scans) {
    scan.stamp_s = in.Get<double>();
    scan.angle_min_rad = in.Get<double>();
    scan.angle_increment_rad = in.Get<double>();
    scan.range_min_m = in.Get<double>();
    scan.range_max_m = in.Get<double>();
    scan.sensor_pose_on_robot = in.PoseOf();
    scan.ranges_m = in.Floats();
  }
  sequence.odometry = in.TrajectoryOf();
  sequence.odometry_readings = in.TrajectoryOf();
  if (in.Get<std::uint8_t>() != 0) sequence.reference = in.TrajectoryOf();
  if (in.Get<std::uint8_t>() != 0) {
    const std::size_t count = in.Count(9 * sizeof(double));
    ev::Relations relations(count);
    for (ev::Relation& relation : relations) {
      relation.t1_s = in.Get<double>();
      relation.t2_s = in.Get<double>();
      relation.delta = in.PoseOf();
    }
    sequence.relations = std::move(relations);
  }
  sequence.relations_outside_log = in.Count(0);
  if (in.Get<std::uint8_t>() != 0) {
    ev::StampFacts facts;
    const auto outcome = in.Get<std::int32_t>();
    if (outcome < static_cast<std::int32_t>(ev::StampOutcome::kRecorded) ||
        outcome > static_cast<std::int32_t>(ev::StampOutcome::kRecordOrder)) {
      throw ev::InputError("prepared sequence: damaged (unknown stamp outcome)");
    }
    facts.outcome = static_cast<ev::StampOutcome>(outcome);
    facts.records = in.Count(0);
    facts.steps_back = in.Count(0);
    facts.duplicates = in.Count(0);
    facts.largest_step_back_s = in.Get<double>();
    facts.changed = in.Count(0);
    facts.largest_change_s = in.Get<double>();
    if (in.Get<std::uint8_t>() != 0) {
      ev::RecordOrderCheck check;
      for (std::size_t* count : {&check.steps, &check.scans_closer_in_file_order, &check.scans_closer_in_stamp_order,
                                 &check.odometry_shorter_in_file_order, &check.odometry_shorter_in_stamp_order}) {
        *count = in.Count(0);
      }
      facts.order_check = check;
    }
    sequence.stamp_facts = facts;
  }
  in.End();
  return sequence;
}

}  // namespace slamsweep::orchestrator::inline input_cache
