#pragma once

#include <string>
#include <string_view>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::orchestrator::inline input_cache {

/// What a run takes from its prepared sequence (name, scans, odometry, odometry readings, reference,
/// relations and how many lie outside the log, warnings, stamp facts) as bytes, every number bit for bit (this
/// machine's byte order: the bytes are a cache, never an exchange format). Provenance and the reference map are not
/// kept: no run reads them.
std::string EncodeSequence(const evaluator::Sequence& sequence);

/// The sequence EncodeSequence wrote. Throws InputError for bytes it did not write (too short, counts
/// past the end, trailing bytes).
evaluator::Sequence DecodeSequence(std::string_view bytes);

}  // namespace slamsweep::orchestrator::inline input_cache
