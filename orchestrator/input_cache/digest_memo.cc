#include "orchestrator/input_cache/digest_memo.h"

#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/build_identity/file_digest.h"
#include "orchestrator/run/stable_hash.h"

namespace slamsweep::orchestrator::inline input_cache {
namespace {

namespace fs = std::filesystem;

/// Seconds a file must have been unchanged before its digest is remembered.
constexpr long kSettledS = 3;

std::string ReadSmallFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string HostName() {
  char name[HOST_NAME_MAX + 1] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  return name;
}

}  // namespace

void ReplaceFile(const fs::path& file, std::string_view content) {
  static std::atomic<unsigned> counter{0};
  static const std::string host = HostName();
  const fs::path temporary =
      file.parent_path() / fmt::format(".{}.tmp-{}-{}-{}", file.filename().string(), host, ::getpid(), counter++);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw evaluator::InputError(temporary.string() + ": cannot write");
    }
  }
  if (::rename(temporary.c_str(), file.c_str()) != 0) {
    const int error = errno;
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw evaluator::InputError(file.string() + ": cannot replace: " + std::strerror(error));
  }
}

std::string MemoisedSha256(const fs::path& file, const fs::path& memo_dir) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0) {
    throw evaluator::InputError(file.string() +
                                ": cannot read the file to compute its digest: " + std::strerror(errno));
  }
  const std::string identity = fmt::format(
      "{}\n{} {} {} {}.{:09} {}.{:09}\n", fs::absolute(file).lexically_normal().string(), info.st_dev, info.st_ino,
      info.st_size, info.st_mtim.tv_sec, info.st_mtim.tv_nsec, info.st_ctim.tv_sec, info.st_ctim.tv_nsec);
  const fs::path memo = memo_dir / fmt::format("{:016x}.sha256", Fnv1a64(identity));
  // The memo holds the identity it was made for, then the digest: another file's memo is never taken.
  const std::string stored = ReadSmallFile(memo);
  if (stored.size() == identity.size() + 65 && stored.starts_with(identity) && stored.back() == '\n') {
    return stored.substr(identity.size(), 64);
  }
  const std::string digest = Sha256OfFile(file);
  // A file changed within the last seconds may change again within one tick of the file system's clock,
  // keeping every time stamp: its digest is not remembered until it has been still for a while.
  timespec now{};
  ::clock_gettime(CLOCK_REALTIME, &now);
  if (now.tv_sec - info.st_ctim.tv_sec < kSettledS || now.tv_sec - info.st_mtim.tv_sec < kSettledS) return digest;
  std::error_code error;
  fs::create_directories(memo_dir, error);
  try {
    if (!error) ReplaceFile(memo, identity + digest + "\n");
  } catch (const evaluator::InputError&) {
    // Not remembered: the next run computes it again.
  }
  return digest;
}

}  // namespace slamsweep::orchestrator::inline input_cache
