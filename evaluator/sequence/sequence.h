#pragma once

#include <optional>
#include <string>
#include <vector>

#include "evaluator/core/laser_scan.h"
#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/relation.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/sequence/scan_stamps.h"

namespace slamsweep::evaluator::inline sequence {

/// Where a sequence comes from, carried into every report that uses it: public datasets must be
/// cited, and their redistribution terms travel with them.
struct Provenance {
  /// Where the data was obtained (repository, commit, path; or a file path when nothing else is known).
  std::string source;
  /// Whom to cite (the original authors / archive).
  std::string citation;
  /// The redistribution terms as far as they are known.
  std::string licence_note;
  /// How the sequence's clock, time maps or relations were established and checked (catalog notes).
  std::string notes;
};

/// Timestamped 2D laser scans with the robot's odometry, optionally the ground truth that makes
/// the run scorable, and its provenance. Invariant (checked by ValidateSequence): scan stamps
/// strictly increase and `odometry` holds exactly one pose per scan with the scan's stamp.
struct Sequence {
  std::string name;
  std::vector<LaserScan> scans;
  /// Robot pose by odometry at each scan, same stamps as `scans`.
  Trajectory odometry;
  /// Every odometry reading the robot recorded, when the log has more of them than scans (a raw
  /// run's wheel odometry between keyframes); empty otherwise. Stamps strictly increase, and each
  /// scan's stamp is one of them.
  Trajectory odometry_readings;
  /// Ground-truth robot poses (any stamps; metrics associate them by time).
  std::optional<Trajectory> reference;
  /// The relations whose two stamps both lie inside the recorded span of the scans (a log may hold
  /// part of a run: its relations outside are not the run's to cover), and how many were outside.
  std::optional<Relations> relations;
  std::size_t relations_outside_log = 0;
  std::optional<OccupancyGrid> reference_map;
  Provenance provenance;
  /// What the reader had to repair or assume, each naming the input file, for the run record.
  std::vector<std::string> warnings;
  /// How the scan stamps were chosen from the recorded ones, when the reader knows (CARMEN logs).
  std::optional<StampFacts> stamp_facts;
};

/// Throws InputError (starting with the sequence name) unless the invariant above holds and every
/// scan is usable: at least one beam, a finite non-zero angle increment, 0 <= range_min_m < range_max_m,
/// finite stamps and a valid sensor pose.
void ValidateSequence(const Sequence& sequence);

/// Whether the odometry is the reference: the reference has a pose at every scan's stamp and each
/// equals the odometry pose there (within 1 um and 1 urad). A program given it is handed the answer.
bool OdometryEqualsReference(const Sequence& sequence);

/// Moves the relations with a stamp outside the log's recorded span (its first to last scan or odometry
/// reading) out of `sequence.relations` into the count `relations_outside_log` (a log of part of a run, or a
/// cut one).
/// No relation left: `relations` is reset. Stamps are on the scans' clock (after any clock map).
void KeepRelationsInsideLog(Sequence& sequence);

}  // namespace slamsweep::evaluator::inline sequence
