#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "evaluator/sequence/sequence.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline input_cache {

/// The folder of a sweep's prepared inputs, OUT/prepared_inputs beside OUT/runs (orchestrator/DESIGN.md),
/// from the run folder OUT/runs/<run-id>; empty for a run folder that is not in a runs/ folder (nothing is
/// cached then: the cache holds the truth, and only a sweep's output folder is hidden from SLAM programs).
std::filesystem::path PreparedInputCacheDir(const std::filesystem::path& run_dir);

/// The same folder from the sweep's output folder: OUT/prepared_inputs.
std::filesystem::path SweepPreparedInputsDir(const std::filesystem::path& output_dir);

/// What a prepared sequence depends on, as JSON: the cache format, this slamsweep's revision and the SHA-256
/// of its executable, the sequence entry (format, paths, reading options, simulation; not what is said about
/// the data: citation, licence, download), max_scans, and the SHA-256 of every file the entry reads (log,
/// relations, corrected log; memoised in `cache_dir`/digests). Noise, seed, iteration and algorithm are not
/// in it: every run of the sequence and cut shares one entry. Throws InputError naming a file that cannot
/// be read.
nlohmann::json PreparedSequenceKey(const RunSpec& spec, const std::filesystem::path& cache_dir);

/// A prepared sequence as an entry's body: every field, every number bit for bit (evaluator::EncodeSequence).
std::string EncodePreparedSequence(const evaluator::Sequence& sequence);

/// The sequence EncodePreparedSequence wrote. Throws InputError for bytes it did not write (too short, counts
/// past the end, trailing bytes).
evaluator::Sequence DecodePreparedSequence(std::string_view bytes);

struct PreparedSequence {
  evaluator::Sequence sequence;
  bool from_cache = false;
  /// Why the prepared sequence could not be stored (it was prepared for this run alone); empty normally.
  std::string cache_problem;
};

/// The run's sequence as `prepare` makes it (read, cut and checked), from `cache_dir` when an entry with
/// exactly this key is there, else prepared, stored and used. The entry, <sequence>-<16 hex digits>.seq,
/// holds its key and a CRC-32 and is renamed into place complete, so workers on any host sharing the folder
/// may make it at once (both write the same bytes); one that is damaged or of another key is made again.
/// Either way the caller gets the sequence decoded from the entry's bytes, so a run's inputs never depend on
/// whether it found the entry. Whatever `prepare` throws is thrown (errors are never cached).
PreparedSequence LoadOrPrepareSequence(const RunSpec& spec, const std::filesystem::path& cache_dir,
                                       const std::function<evaluator::Sequence()>& prepare);

}  // namespace slamsweep::orchestrator::inline input_cache
