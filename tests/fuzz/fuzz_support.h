#pragma once

// What every fuzz target of tests/fuzz shares. A target is one file, <name>_fuzz.cc, that defines
// LLVMFuzzerTestOneInput (what to do with one input) and SLAMSWEEP_FUZZ_SEEDS (the inputs to start from),
// and one line in tests/fuzz/CMakeLists.txt. The normal build links it with replay_main.cc (ctest replays
// the seeds and the kept findings); a fuzz build links it with libFuzzer (docs/hostile-input.md).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::fuzz {

/// The input as bytes.
inline std::string_view Bytes(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Readers take paths: writes `bytes` to `name` in this process's scratch folder (under $TMPDIR, removed
/// at exit) and returns its path. The same name is overwritten by the next input.
std::filesystem::path WriteInput(std::string_view name, std::string_view bytes);

/// `name` in that scratch folder (for inputs that are folders, or files a target writes once).
std::filesystem::path ScratchPath(std::string_view name);

/// Inputs made of several files (a map's YAML and image) hold the files one after the other, separated by
/// kPartSeparator. SplitParts returns `count` parts; the last takes the rest, missing ones are empty.
inline constexpr std::string_view kPartSeparator = "\n--- slamsweep-fuzz-part ---\n";
std::vector<std::string_view> SplitParts(std::string_view input, std::size_t count);
std::string JoinParts(std::initializer_list<std::string_view> parts);

/// The contract of every reader, whatever the input: it returns, or it throws InputError whose message names
/// one of `files` (at least by file name). Anything else is a finding: another exception, or an InputError
/// that does not say where. A finding prints what happened and aborts, which libFuzzer and ctest both catch.
void ExpectReadOrInputError(std::initializer_list<std::filesystem::path> files, const std::function<void()>& read);

/// Whether ExpectReadOrInputError prints each InputError's message (the replay does: its log then says how
/// every kept input is rejected; libFuzzer runs stay quiet).
void SetShowRejections(bool show);

/// Aborts with `what` (a finding) unless `condition` holds.
void Require(bool condition, std::string_view what);

/// Where a target's seeds go, with what they are made from.
class Seeds {
 public:
  Seeds(std::filesystem::path folder, std::filesystem::path shared, std::filesystem::path source);

  /// Writes one seed (replacing an older one of the name).
  void Add(std::string_view name, std::string_view bytes);
  /// The first `max_bytes` of a file under ../shared (inflated first when `inflate` and it is gzip), cut back
  /// to the last whole line when `whole_lines`. Nothing, and the file is listed in Missing(), when it is absent:
  /// datasets are cut when the seeds are written and never copied into the repository.
  std::optional<std::string> SharedHead(const std::filesystem::path& relative, std::size_t max_bytes,
                                        bool inflate = true, bool whole_lines = true);
  /// A whole file under ../shared, or nothing (listed in Missing()).
  std::optional<std::string> SharedFile(const std::filesystem::path& relative);
  /// A file of the source tree (example configs), which must exist.
  std::string SourceFile(const std::filesystem::path& relative) const;
  /// Files of a folder under ../shared, sorted (listed in Missing() when the folder is absent).
  std::vector<std::filesystem::path> SharedFolder(const std::filesystem::path& relative);

  const std::filesystem::path& folder() const { return folder_; }
  const std::filesystem::path& shared() const { return shared_; }
  const std::vector<std::string>& Missing() const { return missing_; }
  std::size_t count() const { return count_; }

 private:
  std::filesystem::path folder_;
  std::filesystem::path shared_;
  std::filesystem::path source_;
  std::vector<std::string> missing_;
  std::size_t count_ = 0;
};

/// gzip of `bytes` (zlib), for seeds of gzip readers.
std::string Gzip(std::string_view bytes);

/// Writes the target's seeds into `folder`; 0 when all were written, 1 when shared data was missing under
/// CI=true (a broken set-up fails), printing what was written and what was missing.
int WriteSeeds(const std::filesystem::path& folder);

}  // namespace slamsweep::fuzz

/// Defined by each target (SLAMSWEEP_FUZZ_SEEDS(seeds) { seeds.Add(...); }).
void SlamsweepFuzzSeeds(slamsweep::fuzz::Seeds& seeds);
#define SLAMSWEEP_FUZZ_SEEDS(seeds) void SlamsweepFuzzSeeds(::slamsweep::fuzz::Seeds& seeds)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
