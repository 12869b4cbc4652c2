#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string_view>

#include "evaluator/format_modules/format_module.h"
#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence_io {

/// What a contained reader may spend: memory beyond what the process held when it forked, CPU time, and
/// wall-clock time (a reader that waits instead of computing).
struct ReaderLimits {
  std::uintmax_t memory_bytes = 0;
  double cpu_s = 0.0;
  double wall_s = 0.0;
};

/// The limits for a file holding `content_bytes` (ContentBytes): 32 MiB + 16 bytes per byte of content
/// (reading a real rawlog or bag takes about 2 bytes per byte), 10 s + 2 s per MiB of CPU time (about 100 times
/// what reading takes), and 4 times that CPU time + 10 s of wall-clock time. An AddressSanitizer build adds 1 GiB
/// of memory: it keeps freed memory in quarantine and needs room for it.
ReaderLimits LimitsForContent(std::uintmax_t content_bytes);

/// How many bytes of content `path` holds: its size; for gzip data, what its trailer claims (ISIZE), at
/// least its size and at most GzipInflateCap of it.
std::uintmax_t ContentBytes(const std::filesystem::path& path);

/// Runs `read` (a format module's read: MRPT for rawlogs, librosbag for ROS1 bags) in a child process under
/// `limits`, and returns the sequence it read. Those libraries allocate what the file declares before they
/// read it, and their formats hold no sizes that could be checked first (MRPT's stream has none at all), so a
/// damaged file could take gigabytes, loop or crash them; the child confines that to itself. Calls are
/// serialised in the process (a fork must not copy another thread's half-done work in the library).
/// Throws InputError located at `file` when the reader reported bad input, needed more memory or time than
/// the limits allow (the message says which limit), or was ended by a signal (a crash in `library`);
/// std::runtime_error when it reported an internal error or ended without reporting.
Sequence ReadContained(const std::filesystem::path& file, std::string_view library, const ReaderLimits& limits,
                       const std::function<ModuleOutcome(Sequence&)>& read);

}  // namespace slamsweep::evaluator::inline sequence_io
