#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace slamsweep::orchestrator::inline run {

/// A mark on a run that every reader of its numbers must see: each one keeps the run's row out of
/// "best" and out of rankings, and is shown beside the row in every table, file and JUnit case.
enum class RunFlag {
  /// The program was handed the reference as odometry (a corrected log without odometry noise):
  /// an upper bound, not a SLAM result.
  kOdometryIsReference,
  /// Reused from an earlier sweep under another build identity or evaluation (`--reuse-stale`).
  kStale,
  /// The program ran without the sandbox (`--allow-unisolated`): it could have read the reference.
  kUnisolated,
};

/// Every flag, in the order files list them.
inline constexpr RunFlag kAllRunFlags[] = {RunFlag::kOdometryIsReference, RunFlag::kStale, RunFlag::kUnisolated};

/// The flag's name in files: "odometry_is_reference", "stale", "unisolated".
std::string_view RunFlagName(RunFlag flag);
/// The inverse of RunFlagName; nullopt for an unknown name.
std::optional<RunFlag> RunFlagFromName(std::string_view name);
/// A short label for tables and JUnit ("odometry = reference", "stale", "unisolated").
std::string_view RunFlagLabel(RunFlag flag);
/// One sentence saying what the flag means for the run's numbers (report notes, JUnit output).
std::string_view RunFlagMeaning(RunFlag flag);

/// The set of flags of one run (or, as a union, of a group of runs). A value type; iteration is in
/// kAllRunFlags order.
class RunFlags {
 public:
  RunFlags() = default;
  RunFlags(std::initializer_list<RunFlag> flags) : flags_(flags) {}

  bool Has(RunFlag flag) const { return flags_.count(flag) != 0; }
  void Set(RunFlag flag, bool on = true);
  bool empty() const { return flags_.empty(); }
  /// Any flag at all keeps a run out of "best" and out of rankings.
  bool ExcludedFromBest() const { return !flags_.empty(); }
  /// This set plus `other`'s flags (a group's flags are the union of its runs').
  RunFlags& operator|=(const RunFlags& other);

  auto begin() const { return flags_.begin(); }
  auto end() const { return flags_.end(); }
  bool operator==(const RunFlags&) const = default;

 private:
  std::set<RunFlag> flags_;
};

/// ["odometry_is_reference", "stale", ...] in kAllRunFlags order.
nlohmann::json ToJson(const RunFlags& flags);
/// Strict: anything but an array of known flag names is an InputError naming `path`. Null is empty.
RunFlags RunFlagsFromJson(const nlohmann::json& json, const std::string& path = "flags");
/// "odometry_is_reference;stale" for CSV cells and SQLite columns; "" when empty.
std::string RunFlagsText(const RunFlags& flags);
/// The inverse of RunFlagsText; unknown names are an InputError naming `what`.
RunFlags RunFlagsFromText(std::string_view text, const std::string& what = "flags");
/// "odometry = reference, stale" for people; "" when empty.
std::string RunFlagsLabel(const RunFlags& flags);

/// A run's flags from its run.json (what was planned) and result.json (what the worker measured and
/// what the orchestrator marked later): the union of both `flags` arrays, plus the older
/// `odometry_is_reference` booleans (result.json's measured value wins over run.json's plan).
/// Either may be null. Malformed `flags` fields are an InputError naming the file.
RunFlags RunFlagsOf(const nlohmann::json& run_json, const nlohmann::json& result_json);

}  // namespace slamsweep::orchestrator::inline run
