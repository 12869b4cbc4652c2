#pragma once

#include <cstddef>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence {

/// The scans [first, first + count) of `sequence` (clamped to its size) with their odometry; odometry
/// readings and reference poses up to the last kept scan's stamp (and from the first kept scan's stamp
/// when scans before it are cut); relations with a stamp outside that span
/// are counted in relations_outside_log (KeepRelationsInsideLog). No scan left is an InputError.
Sequence KeepScanRange(Sequence sequence, std::size_t first, std::size_t count);

/// The scans that cover [from_s, to_s]: from the last scan at or before from_s (else the first) to the first
/// at or after to_s (else the last), so that every stamp of the span lies between two kept scans; as
/// KeepScanRange. A span that misses the scans is an InputError naming it and the sequence's own.
Sequence KeepTimeSpan(Sequence sequence, double from_s, double to_s);

}  // namespace slamsweep::evaluator::inline sequence
