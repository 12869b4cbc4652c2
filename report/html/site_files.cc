#include "report/html/site_files.h"

#include <fstream>

#include "evaluator/core/input_error.h"
#include "report/html/safe_name.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;
using evaluator::InputError;

// Marks a folder as made by this command, so that a re-run may clear it.
constexpr const char* kMarker = ".slamsweep-report";

}  // namespace

void WriteTextFile(const fs::path& path, std::string_view content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out) throw InputError(path.string() + ": cannot write");
}

void MakeDirectories(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw InputError(dir.string() + ": cannot create folder (" + error.message() + ")");
}

void PrepareOutputDir(const fs::path& out_dir) {
  std::error_code error;
  if (fs::exists(out_dir, error)) {
    if (!fs::is_directory(out_dir, error)) throw InputError(out_dir.string() + ": exists and is not a folder");
    const bool empty = fs::directory_iterator(out_dir, error) == fs::directory_iterator();
    if (!empty && !fs::exists(out_dir / kMarker, error)) {
      throw InputError(out_dir.string() + ": not empty and not a slamsweep report; choose another -o folder");
    }
    for (const char* part : {"runs", "sequences", "plots", "files"}) fs::remove_all(out_dir / part, error);
  }
  for (const char* part : {"", "runs", "sequences", "plots", "files"}) MakeDirectories(out_dir / part);
  WriteTextFile(out_dir / kMarker, "made by slamsweep report\n");
}

void LinkOrCopy(const fs::path& from, const fs::path& to, std::error_code& error) {
  fs::remove(to, error);
  fs::create_hard_link(from, to, error);
  if (error) fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
}

bool CopyResultFile(const fs::path& result_dir, const fs::path& out_dir, const char* name) {
  std::error_code error;
  if (!IsRegularFileNoFollow(result_dir / name)) {
    fs::remove(out_dir / name, error);
    return false;
  }
  LinkOrCopy(result_dir / name, out_dir / name, error);
  return !error;
}

}  // namespace slamsweep::report::inline html
