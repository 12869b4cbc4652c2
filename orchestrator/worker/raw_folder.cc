#include "orchestrator/worker/raw_folder.h"

namespace slamsweep::orchestrator::inline worker {
namespace fs = std::filesystem;
namespace {

std::string KindOf(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::symlink:
      return "a symbolic link";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device";
    default:
      return "not a plain file";
  }
}

}  // namespace

RawFolderCheck CheckRawFolder(const fs::path& raw, std::uint64_t file_size_limit_bytes) {
  RawFolderCheck check;
  std::error_code error;
  // Never follows a link: the iterator does not descend into linked folders.
  fs::recursive_directory_iterator it(raw, fs::directory_options::none, error), end;
  for (; !error && it != end; it.increment(error)) {
    const fs::file_status status = it->symlink_status(error);
    if (error) break;
    const std::string name = (raw.filename() / it->path().lexically_relative(raw)).string();
    if (fs::is_directory(status)) continue;
    if (fs::is_regular_file(status)) {
      const std::uint64_t size = it->file_size(error);
      if (error) break;
      check.total_bytes += size;
      if (file_size_limit_bytes > 0 && size >= file_size_limit_bytes && check.file_at_limit.empty()) {
        check.file_at_limit = name;
      }
      continue;
    }
    check.removed.push_back(name + " (" + KindOf(status) + ")");
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
  return check;
}

}  // namespace slamsweep::orchestrator::inline worker
