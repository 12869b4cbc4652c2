#include "orchestrator/sweep/shared_run_files.h"

#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

namespace slamsweep::orchestrator::inline sweep {
namespace {

namespace fs = std::filesystem;

// A shared file is small (a reference trajectory); larger files are left alone.
constexpr std::uintmax_t kMaxSharedBytes = 1 << 20;

std::optional<std::string> Contents(const fs::path& file) {
  std::error_code error;
  if (!fs::is_regular_file(fs::symlink_status(file, error)) || fs::file_size(file, error) > kMaxSharedBytes || error) {
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  std::string text(std::istreambuf_iterator<char>(in), {});
  if (in.bad()) return std::nullopt;
  return text;
}

}  // namespace

void SharedRunFiles::Share(const fs::path& file) {
  std::optional<std::string> contents = Contents(file);
  if (!contents) return;
  const auto found = first_with_content_.find(*contents);
  if (found == first_with_content_.end()) {
    first_with_content_.emplace(std::move(*contents), file);
    return;
  }
  std::error_code error;
  if (fs::equivalent(found->second, file, error)) return;
  if (Contents(found->second) != contents) {
    found->second = file;  // the first one was removed or rewritten (a rerun): this one is the first now
    return;
  }
  // Linked beside it and renamed over it: the run folder always has the file.
  fs::path link = file;
  link += ".shared";
  fs::remove(link, error);
  fs::create_hard_link(found->second, link, error);
  if (error) return;
  fs::rename(link, file, error);
  if (error) fs::remove(link, error);
}

}  // namespace slamsweep::orchestrator::inline sweep
