#include "orchestrator/input_cache/prepared_sequence_cache.h"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <system_error>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/sequence_codec.h"
#include "orchestrator/build_identity/revision.h"
#include "orchestrator/input_cache/digest_memo.h"
#include "orchestrator/run/run_json.h"
#include "orchestrator/run/stable_hash.h"

namespace slamsweep::orchestrator::inline input_cache {
namespace {

namespace fs = std::filesystem;
namespace ev = slamsweep::evaluator;
using nlohmann::json;

/// Raised whenever the entry's layout (evaluator::EncodeSequence's included) or what the key holds changes.
constexpr int kFormat = 3;
constexpr std::string_view kMagic = "SLSWPSQ2";

/// The worker's executable: the code that reads, repairs and cuts the sequence.
std::string ExecutableDigest(const fs::path& memo_dir) {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return "unknown";
  return MemoisedSha256(self, memo_dir);
}

/// The name of a sequence's entry: readable, safe as a file name.
std::string SafeName(std::string_view text) {
  std::string safe;
  for (const char c : text.substr(0, 48)) {
    const bool plain =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
    safe.push_back(plain ? c : '_');
  }
  return safe.empty() || safe.front() == '.' ? "s" + safe : safe;
}

std::uint32_t Crc32(std::string_view key, std::string_view body) {
  uLong crc = crc32(0L, Z_NULL, 0);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(key.data()), static_cast<uInt>(key.size()));
  crc = crc32(crc, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()));
  return static_cast<std::uint32_t>(crc);
}

void PutU64(std::string& out, std::uint64_t value) { out.append(reinterpret_cast<const char*>(&value), 8); }

/// magic, key length, key, body length, body, CRC-32 of key and body.
std::string EntryBytes(const std::string& key, const std::string& body) {
  std::string out(kMagic);
  PutU64(out, key.size());
  out += key;
  PutU64(out, body.size());
  out += body;
  const std::uint32_t crc = Crc32(key, body);
  out.append(reinterpret_cast<const char*>(&crc), 4);
  return out;
}

/// The entry's body when it holds exactly `key` and its CRC matches; nullopt otherwise.
std::optional<std::string_view> EntryBody(std::string_view bytes, const std::string& key) {
  const auto u64 = [&](std::size_t at) {
    std::uint64_t value = 0;
    std::memcpy(&value, bytes.data() + at, 8);
    return value;
  };
  std::size_t at = kMagic.size();
  if (bytes.size() < at + 8 || !bytes.starts_with(kMagic)) return std::nullopt;
  if (u64(at) != key.size() || bytes.size() < at + 8 + key.size() + 8 + 4) return std::nullopt;
  at += 8;
  if (bytes.substr(at, key.size()) != key) return std::nullopt;
  at += key.size();
  const std::uint64_t body_size = u64(at);
  at += 8;
  if (body_size != bytes.size() - at - 4) return std::nullopt;
  const std::string_view body = bytes.substr(at, body_size);
  std::uint32_t crc = 0;
  std::memcpy(&crc, bytes.data() + at + body_size, 4);
  if (crc != Crc32(key, body)) return std::nullopt;
  return body;
}

std::string ReadWhole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::string EncodePreparedSequence(const ev::Sequence& sequence) { return ev::EncodeSequence(sequence); }

ev::Sequence DecodePreparedSequence(std::string_view bytes) {
  try {
    return ev::DecodeSequence(bytes);
  } catch (const ev::DamagedSequenceBytes& error) {
    throw ev::InputError(std::string("prepared sequence: ") + error.what());
  }
}

fs::path PreparedInputCacheDir(const fs::path& run_dir) {
  fs::path dir = run_dir.lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();  // "runs/r1/" -> "runs/r1"
  if (dir.parent_path().filename() != "runs") return {};
  return SweepPreparedInputsDir(dir.parent_path().parent_path());
}

fs::path SweepPreparedInputsDir(const fs::path& output_dir) { return output_dir / "prepared_inputs"; }

json PreparedSequenceKey(const RunSpec& spec, const fs::path& cache_dir) {
  const ev::CatalogEntry& entry = spec.sequence.entry;
  json sequence = ToJson(entry);
  // What is said about the data, not the data.
  for (const char* words : {"citation", "licence", "download"}) sequence.erase(words);
  const fs::path memo_dir = cache_dir / "digests";
  json files = json::object();
  for (const auto& [role, path] : {std::pair<const char*, std::string>{"file", entry.path},
                                   {"relations", entry.relations_path},
                                   {"corrected_log", entry.corrected_log ? entry.corrected_log->path : ""}}) {
    if (!path.empty()) files[role] = MemoisedSha256(path, memo_dir);
  }
  return {{"format", kFormat},
          {"slamsweep", std::string(SlamsweepRevision())},
          {"executable_sha256", ExecutableDigest(memo_dir)},
          {"sequence", std::move(sequence)},
          {"max_scans", spec.sequence.max_scans ? json(*spec.sequence.max_scans) : json()},
          {"files_sha256", std::move(files)}};
}

PreparedSequence LoadOrPrepareSequence(const RunSpec& spec, const fs::path& cache_dir,
                                       const std::function<ev::Sequence()>& prepare) {
  PreparedSequence prepared;
  std::string key;
  fs::path entry;
  try {
    key = PreparedSequenceKey(spec, cache_dir).dump();
    entry = cache_dir / fmt::format("{}-{:016x}.seq", SafeName(spec.sequence.entry.name), Fnv1a64(key));
  } catch (const ev::InputError&) {
    // A file the key cannot digest is one the sequence cannot be read from: `prepare` says so.
    prepared.sequence = prepare();
    return prepared;
  }
  const std::string stored = ReadWhole(entry);
  if (const std::optional<std::string_view> body = EntryBody(stored, key)) {
    try {
      prepared.sequence = DecodePreparedSequence(*body);
      prepared.from_cache = true;
      return prepared;
    } catch (const ev::InputError&) {
      // Made again below.
    }
  }
  const std::string body = EncodePreparedSequence(prepare());
  try {
    std::error_code error;
    fs::create_directories(cache_dir, error);
    if (error) throw ev::InputError(cache_dir.string() + ": cannot create: " + error.message());
    ReplaceFile(entry, EntryBytes(key, body));
  } catch (const ev::InputError& error) {
    prepared.cache_problem = error.what();
  }
  prepared.sequence = DecodePreparedSequence(body);
  return prepared;
}

}  // namespace slamsweep::orchestrator::inline input_cache
