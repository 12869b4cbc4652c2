#include "tests/fuzz/fuzz_support.h"

#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <stdexcept>

#include "evaluator/core/input_error.h"
#include "evaluator/core/text_file.h"
#include "tests/support/shared_data.h"

namespace slamsweep::fuzz {
namespace {

/// The scratch folder, made on first use and removed at exit.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "slamsweep-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a scratch folder in " + pattern);
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

void WriteBytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

bool show_rejections = false;

[[noreturn]] void Finding(std::string_view what) {
  std::cerr << "slamsweep fuzz finding: " << what << std::endl;
  std::abort();
}

}  // namespace

std::filesystem::path ScratchPath(std::string_view name) {
  static const ScratchFolder scratch;
  return scratch.path() / name;
}

std::filesystem::path WriteInput(std::string_view name, std::string_view bytes) {
  const std::filesystem::path path = ScratchPath(name);
  WriteBytes(path, bytes);
  return path;
}

std::vector<std::string_view> SplitParts(std::string_view input, std::size_t count) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < count) {
    const std::size_t at = input.find(kPartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(input.substr(0, at));
    input.remove_prefix(at + kPartSeparator.size());
  }
  parts.push_back(input);
  parts.resize(count);
  return parts;
}

std::string JoinParts(std::initializer_list<std::string_view> parts) {
  std::string joined;
  bool first = true;
  for (std::string_view part : parts) {
    if (!first) joined += kPartSeparator;
    first = false;
    joined += part;
  }
  return joined;
}

void ExpectReadOrInputError(std::initializer_list<std::filesystem::path> files, const std::function<void()>& read) {
  try {
    read();
  } catch (const evaluator::InputError& error) {
    const std::string_view message = error.what();
    const bool located = std::any_of(files.begin(), files.end(), [&](const std::filesystem::path& file) {
      return message.find(file.filename().string()) != std::string_view::npos;
    });
    if (!located) Finding("an InputError that names none of the input files: " + std::string(message));
    if (show_rejections) std::cout << "  rejected: " << message.substr(0, 300) << "\n";
  } catch (const std::exception& error) {
    Finding("an exception other than InputError: " + std::string(error.what()));
  }
}

void SetShowRejections(bool show) { show_rejections = show; }

void Require(bool condition, std::string_view what) {
  if (!condition) Finding(what);
}

Seeds::Seeds(std::filesystem::path folder, std::filesystem::path shared, std::filesystem::path source)
    : folder_(std::move(folder)), shared_(std::move(shared)), source_(std::move(source)) {
  std::filesystem::create_directories(folder_);
}

void Seeds::Add(std::string_view name, std::string_view bytes) {
  WriteBytes(folder_ / name, bytes);
  ++count_;
}

std::optional<std::string> Seeds::SharedFile(const std::filesystem::path& relative) {
  const std::filesystem::path path = shared_ / relative;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    missing_.push_back(path.string());
    return std::nullopt;
  }
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::optional<std::string> Seeds::SharedHead(const std::filesystem::path& relative, std::size_t max_bytes, bool inflate,
                                             bool whole_lines) {
  const std::filesystem::path path = shared_ / relative;
  if (!std::filesystem::exists(path)) {
    missing_.push_back(path.string());
    return std::nullopt;
  }
  std::string text;
  if (inflate) {
    // Inflates the whole file: the shared logs are a few megabytes.
    text = evaluator::ReadTextFile(path);
  } else {
    text = *SharedFile(relative);
  }
  if (text.size() > max_bytes) {
    text.resize(max_bytes);
    if (whole_lines && text.rfind('\n') != std::string::npos) text.resize(text.rfind('\n') + 1);
  }
  return text;
}

std::vector<std::filesystem::path> Seeds::SharedFolder(const std::filesystem::path& relative) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(shared_ / relative, error)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  if (error) missing_.push_back((shared_ / relative).string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string Seeds::SourceFile(const std::filesystem::path& relative) const {
  std::ifstream in(source_ / relative, std::ios::binary);
  if (!in) throw std::runtime_error("seeds: source file missing: " + (source_ / relative).string());
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string Gzip(std::string_view bytes) {
  z_stream stream{};
  if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw std::runtime_error("deflateInit2 failed");
  }
  std::string out(deflateBound(&stream, static_cast<uLong>(bytes.size())) + 64, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int code = deflate(&stream, Z_FINISH);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  if (code != Z_STREAM_END) throw std::runtime_error("deflate failed");
  return out;
}

int WriteSeeds(const std::filesystem::path& folder) {
  Seeds seeds(folder, testing::SharedRoot(), SLAMSWEEP_SOURCE_DIR);
  SlamsweepFuzzSeeds(seeds);
  std::cout << "wrote " << seeds.count() << " seeds into " << folder.string() << "\n";
  for (const std::string& missing : seeds.Missing()) {
    std::cout << "shared data missing, its seeds were not written: " << missing
              << " (expected the read-only shared/ folder beside the repository, or set SLAMSWEEP_SHARED)\n";
  }
  if (!seeds.Missing().empty() && testing::RunningInCi()) {
    std::cout << "under CI=true missing shared data is a failure\n";
    return 1;
  }
  return 0;
}

}  // namespace slamsweep::fuzz
