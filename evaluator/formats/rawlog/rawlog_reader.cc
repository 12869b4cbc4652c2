#include "evaluator/formats/rawlog/rawlog_reader.h"

#include <fmt/format.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <array>
#include <exception>
#include <fstream>
#include <map>
#include <new>
#include <optional>
#include <vector>

#include "evaluator/core/gzip_inflate.h"
#include "evaluator/core/input_error.h"
#include "evaluator/formats/rawlog/mrpt_conversions.h"

namespace slamsweep::evaluator::inline formats::inline rawlog {
namespace {

using internal::FromMrptPose2D;
using internal::FromMrptScan;

/// A scan as read, before its stamp and odometry are settled (both need the whole file).
struct ReadScan {
  LaserScan scan;
  /// Odometry by the actions read before the scan.
  Pose action_odometry;
  /// How many CObservationOdometry came before the scan.
  std::size_t odometry_observations_before = 0;
};

/// Everything gathered in one pass over the file's objects.
struct ReadState {
  std::optional<std::string> scan_label;
  std::vector<ReadScan> scans;
  bool any_movement = false;
  Pose action_odometry;
  std::vector<Pose> odometry_observations;
  RawlogSummary summary;
  std::map<std::string, std::size_t> other_label_scans;
  std::size_t short_scans = 0;
  std::map<std::string, std::size_t> ignored_classes;
};

std::string DefaultName(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  for (std::string_view suffix : {".gz", ".rawlog"}) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) name.resize(name.size() - suffix.size());
  }
  return name;
}

/// What an exception says. MRPT's exceptions nest ("==== MRPT exception ====\nMessage: ...\n
/// Location: ...\nCall stack backtrace: ..." around the exception they wrap): the innermost
/// message is the cause; its source location and call trace mean nothing to a user.
std::string ExceptionText(const char* what) {
  constexpr std::string_view kBanner = "==== MRPT exception ====";
  const std::string all(what);
  const std::size_t banner = all.rfind(kBanner);
  if (banner == std::string::npos) return all.substr(0, all.find('\n'));
  std::string message;
  std::string location;
  std::string* field = nullptr;
  std::size_t start = banner + kBanner.size();
  while (start < all.size()) {
    std::size_t end = all.find('\n', start);
    if (end == std::string::npos) end = all.size();
    std::string_view line(all.data() + start, end - start);
    start = end + 1;
    if (line.starts_with("Call stack")) break;
    if (line.starts_with("Message:")) {
      field = &message;
      line.remove_prefix(8);
    } else if (line.starts_with("Location:")) {
      field = &location;
      line.remove_prefix(9);
    }
    const std::size_t first = line.find_first_not_of(' ');
    if (field == nullptr || first == std::string_view::npos) continue;
    if (!field->empty()) *field += ' ';
    *field += line.substr(first);
  }
  return message.empty() ? location : message;
}

bool IsGzipFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 2> magic{};
  in.read(magic.data(), 2);
  return HasGzipMagic(std::string_view(magic.data(), static_cast<std::size_t>(in.gcount())));
}

std::string ClassName(const mrpt::serialization::CSerializable& object) { return object.GetRuntimeClass()->className; }

void TakeObservation(const mrpt::obs::CObservation::Ptr& observation, const RawlogReadOptions& options,
                     ReadState& state) {
  if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(observation.get())) {
    if (!state.scan_label) state.scan_label = options.scan_label.empty() ? scan->sensorLabel : options.scan_label;
    if (scan->sensorLabel != *state.scan_label) {
      ++state.other_label_scans[scan->sensorLabel];
      return;
    }
    if (scan->getScanSize() < 2) {
      ++state.short_scans;
      return;
    }
    state.scans.push_back({FromMrptScan(*scan), state.action_odometry, state.odometry_observations.size()});
  } else if (const auto* odometry = dynamic_cast<const mrpt::obs::CObservationOdometry*>(observation.get())) {
    state.odometry_observations.push_back(FromMrptPose2D(odometry->odometry));
  } else {
    ++state.ignored_classes[ClassName(*observation)];
  }
}

void TakeObject(const mrpt::serialization::CSerializable::Ptr& object, const RawlogReadOptions& options,
                ReadState& state) {
  if (const auto* actions = dynamic_cast<const mrpt::obs::CActionCollection*>(object.get())) {
    ++state.summary.actions;
    if (const auto movement = actions->getBestMovementEstimation(); movement && movement->poseChange) {
      state.any_movement = true;
      state.action_odometry = state.action_odometry * FromMrptPose2D(movement->poseChange->getMeanVal());
    }
  } else if (const auto* frame = dynamic_cast<const mrpt::obs::CSensoryFrame*>(object.get())) {
    ++state.summary.sensory_frames;
    for (const mrpt::obs::CObservation::Ptr& observation : *frame) TakeObservation(observation, options, state);
  } else if (const auto observation = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
    ++state.summary.observations;
    TakeObservation(observation, options, state);
  } else {
    ++state.ignored_classes[ClassName(*object)];
  }
}

ReadState ReadObjects(const std::filesystem::path& path, const RawlogReadOptions& options) {
  std::error_code missing;
  if (!std::filesystem::is_regular_file(path, missing)) {
    throw InputError(Located(path, 0, "cannot open the rawlog: no such file"));
  }
  mrpt::io::CFileGZInputStream stream;
  std::string error;
  bool opened = false;
  try {
    opened = stream.open(path.string(), error);
  } catch (const std::exception& failure) {
    error = ExceptionText(failure.what());
  }
  if (!opened) throw InputError(Located(path, 0, "cannot open the rawlog: " + error));
  auto archive = mrpt::serialization::archiveFrom(stream);
  // MRPT inflates gzip data as it reads: the cap of every reader of slamsweep applies to what it has inflated.
  const std::size_t file_bytes = static_cast<std::size_t>(std::filesystem::file_size(path, missing));
  const bool gzip = IsGzipFile(path);
  ReadState state;
  std::size_t object_index = 0;
  while (true) {
    const uint64_t position = stream.getPosition();
    if (gzip && position > GzipInflateCap(file_bytes)) {
      throw InputError(Located(path, 0, GzipInflateCapMessage(file_bytes)));
    }
    mrpt::serialization::CSerializable::Ptr object;
    try {
      object = archive.ReadObject();
    } catch (const mrpt::serialization::CExceptionEOF&) {
      // End of file between objects is the normal end; inside one it is a truncated file.
      if (stream.getPosition() == position) break;
      throw InputError(Located(path, 0, fmt::format("truncated rawlog: object {} ends early", object_index)));
    } catch (const std::bad_alloc&) {
      // MRPT allocates what an object declares before reading it; the process reading is limited in memory.
      throw InputError(Located(path, 0,
                               fmt::format("object {} cannot be read: it declares more data than memory allows for a "
                                           "file of this size (the file is damaged or hostile)",
                                           object_index)));
    } catch (const std::exception& failure) {
      // MRPT rethrows an end of file met inside a nested object as a plain exception saying "(EOF?)".
      const std::string cause = ExceptionText(failure.what());
      const bool truncated = cause.find("(EOF?)") != std::string::npos && stream.getPosition() != position;
      throw InputError(Located(path, 0,
                               truncated ? fmt::format("truncated rawlog: object {} ends early", object_index)
                                         : fmt::format("object {} cannot be read: {}", object_index, cause)));
    }
    if (object) TakeObject(object, options, state);
    ++object_index;
  }
  return state;
}

/// The odometry pose of every scan, with a warning when the file holds none.
std::vector<Pose> ScanOdometry(const ReadState& state, const std::filesystem::path& path,
                               std::vector<std::string>& warnings) {
  std::vector<Pose> poses;
  poses.reserve(state.scans.size());
  if (!state.any_movement && state.odometry_observations.empty()) {
    warnings.push_back(Located(path, 0,
                               "no odometry (neither CActionRobotMovement2D nor CObservationOdometry); every scan "
                               "is given the origin as its odometry pose"));
  }
  for (const ReadScan& scan : state.scans) {
    if (state.any_movement || state.odometry_observations.empty()) {
      poses.push_back(scan.action_odometry);
    } else {
      const std::size_t before = scan.odometry_observations_before;
      poses.push_back(state.odometry_observations[before > 0 ? before - 1 : 0]);
    }
  }
  return poses;
}

void WarnAboutSkipped(const ReadState& state, const std::filesystem::path& path, std::vector<std::string>& warnings) {
  for (const auto& [label, count] : state.other_label_scans) {
    warnings.push_back(Located(
        path, 0,
        fmt::format("{} 2D scans labelled '{}' skipped (reading '{}')", count, label, state.scan_label.value_or(""))));
  }
  if (state.short_scans > 0) {
    warnings.push_back(Located(path, 0, fmt::format("{} 2D scans with fewer than 2 beams skipped", state.short_scans)));
  }
  for (const auto& [name, count] : state.ignored_classes) {
    warnings.push_back(Located(path, 0, fmt::format("{} objects of class {} ignored", count, name)));
  }
}

std::vector<double> ChosenStamps(const ReadState& state, const std::filesystem::path& path, const StampOptions& options,
                                 std::vector<std::string>& warnings) {
  std::vector<double> recorded;
  recorded.reserve(state.scans.size());
  for (const ReadScan& scan : state.scans) recorded.push_back(scan.scan.stamp_s);
  ScanStamps stamps = ChooseScanStamps(recorded, options);
  if (stamps.non_increasing.empty()) return std::move(stamps.stamps_s);
  const std::size_t first = stamps.non_increasing.front();
  if (options.policy == StampPolicy::kRecorded) {
    throw InputError(Located(path, 0,
                             fmt::format("scan {}: timestamp {} does not come after the previous scan's {} (stamp "
                                         "policy 'recorded')",
                                         first, recorded[first], recorded[first - 1])));
  }
  if (stamps.outcome == StampOutcome::kRepaired) {
    warnings.push_back(
        Located(path, 0,
                fmt::format("{} of {} scan stamps did not come after the previous one and were lifted "
                            "to it + {} s (first: scan {})",
                            stamps.non_increasing.size(), recorded.size(), options.repair_step_s, first)));
  } else if (options.policy == StampPolicy::kAuto) {
    warnings.push_back(
        Located(path, 0,
                fmt::format("recorded scan stamps are unusable ({} of {} do not come after the previous "
                            "one, first: scan {}); scans are stamped in record order every {} s instead",
                            stamps.non_increasing.size(), recorded.size(), first, options.record_order_period_s)));
  }
  return std::move(stamps.stamps_s);
}

}  // namespace

RawlogContents ReadRawlogContents(const std::filesystem::path& path, const RawlogReadOptions& options) {
  CheckStampOptions(options.stamps);
  ReadState state = ReadObjects(path, options);
  if (state.scans.empty()) {
    throw InputError(
        Located(path, 0,
                fmt::format("no usable 2D laser scan{} ({} actions, {} sensory frames, {} observations)",
                            options.scan_label.empty() ? "" : " labelled '" + options.scan_label + "'",
                            state.summary.actions, state.summary.sensory_frames, state.summary.observations)));
  }
  RawlogContents contents;
  Sequence& sequence = contents.sequence;
  sequence.name = options.name.empty() ? DefaultName(path) : options.name;
  sequence.provenance.source = path.string();
  WarnAboutSkipped(state, path, sequence.warnings);
  const std::vector<Pose> odometry = ScanOdometry(state, path, sequence.warnings);
  const std::vector<double> stamps_s = ChosenStamps(state, path, options.stamps, sequence.warnings);

  contents.summary = state.summary;
  contents.summary.scans = state.scans.size();
  contents.summary.first_stamp_s = state.scans.front().scan.stamp_s;
  contents.summary.last_stamp_s = state.scans.back().scan.stamp_s;
  sequence.scans.reserve(state.scans.size());
  sequence.odometry.Reserve(state.scans.size());
  for (std::size_t i = 0; i < state.scans.size(); ++i) {
    LaserScan scan = std::move(state.scans[i].scan);
    scan.stamp_s = stamps_s[i];
    sequence.scans.push_back(std::move(scan));
    sequence.odometry.Add(stamps_s[i], odometry[i]);
  }
  return contents;
}

Sequence ReadRawlog(const std::filesystem::path& path, const RawlogReadOptions& options) {
  return ReadRawlogContents(path, options).sequence;
}

}  // namespace slamsweep::evaluator::inline formats::inline rawlog
