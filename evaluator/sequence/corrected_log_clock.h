#pragma once

#include <cstddef>
#include <filesystem>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence {

/// Gives `sequence`, a log that keeps every `every`-th raw scan of a run, the clock of the run's
/// corrected log `corrected` (read with recorded odometry, so that it has one reading per raw scan):
/// scan first_scan + j is stamped like reading first_reading + every * j; the scans before
/// first_scan are dropped (a warning says how many). The corrected
/// log's reference and relations (already on its readings' clock) become the sequence's. Scans both
/// logs hold (the same stamp) must have identical ranges: the check that the map is right. Throws
/// InputError naming `corrected_source` when it has no readings, too few of them, or a shared scan
/// differs. The scans' own odometry is kept.
void TakeClockFromCorrectedLog(Sequence& sequence, Sequence corrected, std::size_t first_scan,
                               std::size_t first_reading, std::size_t every,
                               const std::filesystem::path& corrected_source);

}  // namespace slamsweep::evaluator::inline sequence
