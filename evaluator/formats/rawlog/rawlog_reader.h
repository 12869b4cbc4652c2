#pragma once

#include <filesystem>
#include <string>

#include "evaluator/formats/rawlog/rawlog_writer.h"
#include "evaluator/sequence/scan_stamps.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline formats::inline rawlog {

struct RawlogReadOptions {
  /// Empty: the file name without ".gz" and ".rawlog".
  std::string name;
  /// The 2D scans to read. Empty: the label of the first CObservation2DRangeScan in the file; scans
  /// with another label are counted in a warning.
  std::string scan_label;
  /// Scan stamps are the observations' timestamps, chosen under this policy (see ChooseScanStamps):
  /// carmen2rawlog, for one, stamps every observation with the same instant.
  StampOptions stamps;
};

/// What was read, in MRPT's terms, next to the sequence.
struct RawlogContents {
  Sequence sequence;
  RawlogSummary summary;
};

/// Reads an MRPT rawlog (gzip or plain) in either form, or a mix of both:
///  - Actions/SensoryFrames: odometry = the composition of the CActionRobotMovement2D increments (the
///    mean of each pose-change PDF) read so far, starting at the origin; a CSensoryFrame's 2D scans
///    are taken at that pose.
///  - Observations: odometry of a scan = the last CObservationOdometry before it in the file (or the
///    first after it, for scans before any). Without odometry of either kind every scan gets the
///    origin, with a warning.
/// Scans: see FromMrptScan (the sensor pose holds MRPT's symmetric fan). Scans with fewer than 2
/// beams are skipped with a warning. No reference trajectory (a rawlog holds none); provenance.source
/// is the path. Throws InputError naming the file when it cannot be opened, holds an object MRPT
/// cannot read, or holds no 2D scan.
RawlogContents ReadRawlogContents(const std::filesystem::path& path, const RawlogReadOptions& options = {});

/// ReadRawlogContents(...).sequence.
Sequence ReadRawlog(const std::filesystem::path& path, const RawlogReadOptions& options = {});

}  // namespace slamsweep::evaluator::inline formats::inline rawlog
