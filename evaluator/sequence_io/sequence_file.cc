#include "evaluator/sequence_io/sequence_file.h"

#include <fmt/format.h>
#include <zlib.h>

#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/contained_read.h"
#include "evaluator/sequence_io/format_modules.h"

namespace slamsweep::evaluator::inline sequence_io {
namespace {

bool EndsWith(const std::string& text, std::string_view suffix) { return text.ends_with(suffix); }

/// A ROS 2 storage file by its name (.db3, .mcap, also compressed whole: .zstd) or the MCAP magic.
bool LooksLikeRosbag2File(const std::filesystem::path& path, std::string_view head) {
  std::string name = path.filename().string();
  if (EndsWith(name, ".zstd")) name.resize(name.size() - 5);
  return EndsWith(name, ".db3") || EndsWith(name, ".mcap") || head.starts_with("\x89MCAP0\r\n");
}

/// Up to `count` bytes of the file's content, inflated when it is gzip.
std::string PeekContent(const std::filesystem::path& path, std::size_t count) {
  struct GzCloser {
    void operator()(gzFile_s* file) const { gzclose(file); }
  };
  std::unique_ptr<gzFile_s, GzCloser> file(gzopen(path.c_str(), "rb"));
  if (!file) throw InputError(Located(path, 0, "cannot open file for reading"));
  std::string content(count, '\0');
  const int read = gzread(file.get(), content.data(), static_cast<unsigned>(count));
  content.resize(read > 0 ? static_cast<std::size_t>(read) : 0);
  return content;
}

bool HasGzipMagic(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 2> magic{};
  in.read(magic.data(), 2);
  return in.gcount() == 2 && static_cast<unsigned char>(magic[0]) == 0x1f &&
         static_cast<unsigned char>(magic[1]) == 0x8b;
}

/// Whether the first record of `text` (after blank and `#` lines) is a CARMEN message.
bool LooksLikeCarmen(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    const std::string_view rest = line.substr(first);
    const std::string_view word = rest.substr(0, rest.find_first_of(" \t\r"));
    for (std::string_view message :
         {"FLASER", "RLASER", "ROBOTLASER1", "RAWLASER1", "ODOM", "PARAM", "NEFF", "TRUEPOS", "SYNC"}) {
      if (word == message) return true;
    }
    return false;
  }
  return false;
}

}  // namespace

std::string_view SequenceFormatName(SequenceFormat format) {
  switch (format) {
    case SequenceFormat::kCarmen:
      return "carmen";
    case SequenceFormat::kRawlog:
      return "rawlog";
    case SequenceFormat::kRosbag:
      return "rosbag";
    case SequenceFormat::kRosbag2:
      return "rosbag2";
  }
  return "unknown";
}

SequenceFormat ParseSequenceFormat(std::string_view text, std::string_view option) {
  for (SequenceFormat format :
       {SequenceFormat::kCarmen, SequenceFormat::kRawlog, SequenceFormat::kRosbag, SequenceFormat::kRosbag2}) {
    if (text == SequenceFormatName(format)) return format;
  }
  throw InputError(fmt::format("{}: expected carmen, rawlog, rosbag or rosbag2, got '{}'", option, text));
}

bool RawlogSupported() { return RawlogModuleAvailable(); }

bool RosbagSupported() { return RosbagModuleAvailable(); }

SequenceFormat DetectSequenceFormat(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    // A folder is a ROS 2 bag; one without metadata.yaml is reported by its reader.
    return SequenceFormat::kRosbag2;
  }
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError(Located(
        path, 0, "no such file (expected a sequence: CARMEN log, MRPT rawlog, ROS 1 bag or ROS 2 bag folder or file)"));
  }
  std::string name = path.filename().string();
  if (EndsWith(name, ".bag")) return SequenceFormat::kRosbag;
  if (LooksLikeRosbag2File(path, "")) return SequenceFormat::kRosbag2;
  if (EndsWith(name, ".gz")) name.resize(name.size() - 3);
  if (EndsWith(name, ".rawlog")) return SequenceFormat::kRawlog;
  for (std::string_view suffix : {".log", ".clf"}) {
    if (EndsWith(name, suffix)) return SequenceFormat::kCarmen;
  }
  const std::string head = PeekContent(path, 4096);
  if (head.starts_with("#ROSBAG")) return SequenceFormat::kRosbag;
  if (LooksLikeRosbag2File(path, head)) return SequenceFormat::kRosbag2;
  if (LooksLikeCarmen(head)) return SequenceFormat::kCarmen;
  if (HasGzipMagic(path)) return SequenceFormat::kRawlog;
  throw InputError(Located(path, 0,
                           "unknown sequence format: expected a CARMEN log (.log, .clf, optionally .gz), an "
                           "MRPT rawlog (.rawlog), a ROS 1 bag (.bag) or a ROS 2 bag (a folder with "
                           "metadata.yaml, a .db3 or .mcap file)"));
}

std::vector<std::filesystem::path> SequenceFiles(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    std::vector<std::filesystem::path> files;
    ThrowIfFailed(LoadRosbag2Module(path).files(path, files));
    return files;
  }
  if (!std::filesystem::is_regular_file(path, error)) throw InputError(Located(path, 0, "no such file"));
  return {path};
}

Sequence ReadSequence(const std::filesystem::path& path, const SequenceReadOptions& options) {
  switch (DetectSequenceFormat(path)) {
    case SequenceFormat::kCarmen: {
      CarmenSequenceOptions carmen = options.carmen;
      if (!options.name.empty()) carmen.name = options.name;
      return ReadCarmenSequence(path, carmen);
    }
    case SequenceFormat::kRawlog: {
      const RawlogModule& module = LoadRawlogModule(path);
      RawlogReadOptions rawlog;
      rawlog.name = options.name;
      rawlog.stamps = options.rawlog_stamps;
      return ReadContained(path, "MRPT's rawlog reader", LimitsForContent(ContentBytes(path)),
                           [&](Sequence& sequence) { return module.read(path, rawlog, sequence); });
    }
    case SequenceFormat::kRosbag: {
      const RosbagModule& module = LoadRosbagModule(path);
      const BagReadOptions bag{options.name, options.bag, std::nullopt};
      return ReadContained(path, "librosbag", LimitsForContent(ContentBytes(path)),
                           [&](Sequence& sequence) { return module.read(path, bag, sequence); });
    }
    case SequenceFormat::kRosbag2: {
      // Our own reader (MCAP, sqlite3 and CDR checked against the bytes left): read in this process.
      Sequence sequence;
      ThrowIfFailed(
          LoadRosbag2Module(path).read(path, BagReadOptions{options.name, options.bag, std::nullopt}, sequence));
      return sequence;
    }
  }
  throw InputError(Located(path, 0, "unknown sequence format"));
}

}  // namespace slamsweep::evaluator::inline sequence_io
