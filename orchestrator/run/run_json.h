#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "evaluator/catalog/catalog.h"
#include "orchestrator/run/run_spec.h"
#include "orchestrator/run/run_status.h"

namespace slamsweep::orchestrator::inline run {

/// run.json, as in orchestrator/DESIGN.md. FromJson is strict: an unknown or mistyped field is an
/// InputError naming its path ("run.json: algorithm.timeout_s: expected a number").
nlohmann::json ToJson(const RunSpec& spec);
RunSpec RunSpecFromJson(const nlohmann::json& json);

nlohmann::json ToJson(const evaluator::CatalogEntry& entry);
evaluator::CatalogEntry CatalogEntryFromJson(const nlohmann::json& json, const std::string& path = "sequence");

/// Whether run.json's recorded `evaluation` block scores a run as `current` does (fields a run.json
/// leaves out take their defaults, so one written before a field existed matches the default). An
/// unreadable block is not the same. A finished run scored otherwise is not reused: its numbers would
/// not be comparable with the new runs of its group (say, segment RPE at other lengths).
bool SameEvaluation(const nlohmann::json& recorded_evaluation, const EvaluationOptions& current);

/// BuildSignature of run.json's "build" block; "" when the run.json has none or it is unreadable.
std::string BuildSignatureOfRunJson(const nlohmann::json& run_json);
/// The odometry mode of a run whose run.json names neither the mode nor the sequence's format and ground truth.
inline constexpr std::string_view kOdometryUnknown = "unknown";
/// The odometry mode a run got, from its run.json: group.odometry where the planner wrote it (OdometryModeOf);
/// for a run planned before the mode existed, "reference" on a corrected CARMEN log (its programs got the logged
/// pose, the only odometry those builds gave) and "recorded" on every other log (it has no other odometry);
/// kOdometryUnknown when the run.json names neither the mode nor the sequence's format and ground truth.
std::string OdometryModeOfRunJson(const nlohmann::json& run_json);
/// For notes: "slamsweep <revision>; <file name> <first 12 digits of its digest>, ...".
std::string BuildDescriptionOfRunJson(const nlohmann::json& run_json);

/// The revision of a built-in adapter's own settings (1 for adapters that never changed them, and
/// for unknown names). Part of the run identity from 2 on: results of an adapter whose defaults
/// changed are not reused by a re-run into the same output folder.
int AdapterRevision(const std::string& adapter);

/// The part of a run that decides its result (algorithm, sequence, noise, iteration, seed) as
/// canonical JSON; its hash names the run, so an unchanged run keeps its id across sweeps.
/// The sequence's citation, licence and download texts are left out: they do not change a result.
nlohmann::json RunIdentity(const RunSpec& spec);

/// result.json's status: kOk or kFailed as recorded; a result.json without one counts as failed, and one with
/// any other text (or no object at all) has none.
std::optional<RunStatus> StatusOfResultJson(const nlohmann::json& result);

}  // namespace slamsweep::orchestrator::inline run
