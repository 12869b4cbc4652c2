#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence_io {

/// Bytes that are not a sequence EncodeSequence wrote (too short, a count past the end, bytes left over).
class DamagedSequenceBytes : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Every field of a Sequence as bytes, every number bit for bit: name, scans, odometry and its readings,
/// reference, relations and the count outside the log, reference map, provenance, warnings, stamp facts.
/// For a sequence read in a child process handed back to its parent (contained_read.h) and for the sweep's
/// prepared inputs (orchestrator/input_cache). The layout is this machine's (byte order, sizes), with no
/// version: a store of these bytes keys them by the build that wrote them.
std::string EncodeSequence(const Sequence& sequence);

/// The sequence EncodeSequence wrote. Throws DamagedSequenceBytes for anything else; a count is checked
/// against the bytes left before anything is allocated for it.
Sequence DecodeSequence(std::string_view bytes);

}  // namespace slamsweep::evaluator::inline sequence_io
