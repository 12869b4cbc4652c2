#include "evaluator/sequence_io/format_modules.h"

#include <dlfcn.h>

#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "evaluator/core/installation.h"

namespace slamsweep::evaluator::inline sequence_io {
namespace {

constexpr std::string_view kMrptMissing =
    "MRPT rawlog support not built (install libmrpt-obs-dev and reconfigure slamsweep)";
constexpr std::string_view kRosbagMissing =
    "ROS bag support not built (install librosbag-dev libsensor-msgs-dev libnav-msgs-dev libtf2-msgs-dev "
    "and reconfigure slamsweep)";

/// One module: its file, entry point and what is missing when it was not built. The load is
/// attempted once; its result (the calls, or why there are none) is kept.
template <typename Calls>
class ModuleSlot {
 public:
  ModuleSlot(std::string_view support, bool built, std::string_view file_name, const char* entry,
             std::string_view not_built)
      : support_(support), built_(built), file_name_(file_name), entry_(entry), not_built_(not_built) {}

  const Calls* Get(std::string& why_not) {
    std::call_once(once_, [this] { Load(); });
    why_not = why_not_;
    return calls_;
  }

 private:
  void Load() {
    if (!built_) {
      why_not_ = not_built_;
      return;
    }
    const std::optional<std::filesystem::path> path = FindLibexecFile(file_name_);
    if (!path) {
      why_not_ =
          std::string(support_) + ": module " + std::string(file_name_) + " not found; " + DescribeLibexecSearch();
      return;
    }
    // RTLD_LOCAL: the module's own copies of slamsweep code and its libraries stay private to it.
    void* handle = dlopen(path->c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      why_not_ = "cannot load " + path->string() + ": " + dlerror();
      return;
    }
    using Entry = const Calls* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, entry_));
    const Calls* calls = entry != nullptr ? entry() : nullptr;
    if (calls == nullptr || calls->version != kFormatModuleVersion || calls->layout != FormatModuleLayout()) {
      why_not_ = path->string() + " is not a format module of this slamsweep build (rebuild slamsweep)";
      return;
    }
    calls_ = calls;  // the handle stays open for the rest of the process
  }

  std::string_view support_;
  bool built_;
  std::string_view file_name_;
  const char* entry_;
  std::string_view not_built_;
  std::once_flag once_;
  const Calls* calls_ = nullptr;
  std::string why_not_;
};

ModuleSlot<RawlogModule>& RawlogSlot() {
#ifdef SLAMSWEEP_HAVE_MRPT
  constexpr bool kBuilt = true;
#else
  constexpr bool kBuilt = false;
#endif
  static ModuleSlot<RawlogModule> slot("MRPT rawlog support", kBuilt, "slamsweep-rawlog.so", "slamsweep_rawlog_module",
                                       kMrptMissing);
  return slot;
}

ModuleSlot<RosbagModule>& RosbagSlot() {
#ifdef SLAMSWEEP_HAVE_ROSBAG
  constexpr bool kBuilt = true;
#else
  constexpr bool kBuilt = false;
#endif
  static ModuleSlot<RosbagModule> slot("ROS bag support", kBuilt, "slamsweep-rosbag.so", "slamsweep_rosbag_module",
                                       kRosbagMissing);
  return slot;
}

ModuleSlot<Rosbag2Module>& Rosbag2Slot() {
  // Always built: its libraries (SQLite, zstd, lz4) are slamsweep's own build dependencies.
  static ModuleSlot<Rosbag2Module> slot("ROS 2 bag support", true, "slamsweep-rosbag2.so", "slamsweep_rosbag2_module",
                                        "");
  return slot;
}

template <typename Calls>
const Calls& Require(ModuleSlot<Calls>& slot, const std::filesystem::path& file) {
  std::string why_not;
  const Calls* calls = slot.Get(why_not);
  if (calls == nullptr) throw InputError(Located(file, 0, why_not));
  return *calls;
}

}  // namespace

const RawlogModule& LoadRawlogModule(const std::filesystem::path& file) { return Require(RawlogSlot(), file); }

const RosbagModule& LoadRosbagModule(const std::filesystem::path& file) { return Require(RosbagSlot(), file); }

const Rosbag2Module& LoadRosbag2Module(const std::filesystem::path& file) { return Require(Rosbag2Slot(), file); }

bool RawlogModuleAvailable() {
  std::string why_not;
  return RawlogSlot().Get(why_not) != nullptr;
}

bool RosbagModuleAvailable() {
  std::string why_not;
  return RosbagSlot().Get(why_not) != nullptr;
}

void ThrowIfFailed(const ModuleOutcome& outcome) {
  switch (outcome.kind) {
    case ModuleOutcome::Kind::kOk:
      return;
    case ModuleOutcome::Kind::kInputError:
      throw InputError(outcome.message);
    case ModuleOutcome::Kind::kInternalError:
      throw std::runtime_error(outcome.message);
  }
}

}  // namespace slamsweep::evaluator::inline sequence_io
