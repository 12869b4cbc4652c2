#include "orchestrator/reference_map/reference_map_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <optional>
#include <system_error>

#include <fmt/format.h>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "orchestrator/files/atomic_file.h"

namespace slamsweep::orchestrator::inline reference_map {
namespace {

namespace fs = std::filesystem;
namespace ev = slamsweep::evaluator;

/// An exclusive flock held for the object's lifetime (released by close, also when the process dies).
class ExclusiveLock {
 public:
  explicit ExclusiveLock(const fs::path& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ < 0)
      throw fs::filesystem_error("cannot open the lock file", path, std::error_code(errno, std::generic_category()));
    while (::flock(fd_, LOCK_EX) != 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd_);
      throw fs::filesystem_error("cannot lock", path, std::error_code(error, std::generic_category()));
    }
  }
  ~ExclusiveLock() { ::close(fd_); }
  ExclusiveLock(const ExclusiveLock&) = delete;
  ExclusiveLock& operator=(const ExclusiveLock&) = delete;

 private:
  int fd_;
};

/// The stored map when its key file holds exactly `key` and the map reads; nullopt otherwise.
std::optional<ev::OccupancyGrid> TryRead(const fs::path& yaml, const fs::path& key_file, const nlohmann::json& key) {
  std::ifstream in(key_file, std::ios::binary);
  if (!in) return std::nullopt;
  try {
    if (nlohmann::json::parse(in) != key) return std::nullopt;
    return ev::ReadMapServer(yaml);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  } catch (const ev::InputError&) {
    return std::nullopt;
  }
}

}  // namespace

MapCache::Entry MapCache::LoadOrRender(const std::string& name, const nlohmann::json& key,
                                       const std::function<ev::OccupancyGrid()>& render) const {
  fs::create_directories(dir_);
  const ExclusiveLock lock(dir_ / (name + ".lock"));
  const fs::path yaml = dir_ / (name + ".yaml");
  const fs::path key_file = dir_ / (name + ".key.json");
  if (std::optional<ev::OccupancyGrid> stored = TryRead(yaml, key_file, key)) return {std::move(*stored), yaml, true};

  const ev::OccupancyGrid grid = render();
  // Written complete under temporary names, then renamed into place: the key file last, so a
  // crash at any point leaves an entry that TryRead refuses, never a half-written map it accepts.
  static std::atomic<unsigned> counter{0};
  const fs::path staging = dir_ / fmt::format(".staging-{}-{}-{}", name, ::getpid(), counter++);
  fs::remove_all(staging);
  fs::create_directories(staging);
  ev::WriteMapServer(grid, staging / (name + ".yaml"));
  fs::rename(staging / (name + ".pgm"), dir_ / (name + ".pgm"));
  fs::rename(staging / (name + ".yaml"), yaml);
  fs::remove_all(staging);
  WriteFileAtomically(key_file, key.dump(2) + "\n");
  std::optional<ev::OccupancyGrid> stored = TryRead(yaml, key_file, key);
  if (!stored) throw ev::InputError(yaml.string() + ": the map just written cannot be read back");
  return {std::move(*stored), yaml, false};
}

}  // namespace slamsweep::orchestrator::inline reference_map
