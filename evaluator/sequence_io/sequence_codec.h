#pragma once

#include <string>
#include <string_view>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence_io {

/// Every field of a Sequence as bytes, for handing a sequence read in a child process back to its parent
/// (contained_read.h). Both ends are the same program: the layout is the machine's, with no version.
std::string EncodeSequence(const Sequence& sequence);

/// The sequence EncodeSequence wrote. Throws std::runtime_error when the bytes end early or hold
/// anything else: they come from our own child, so that is a fault of ours, not bad input.
Sequence DecodeSequence(std::string_view bytes);

}  // namespace slamsweep::evaluator::inline sequence_io
