#include "orchestrator/store/validity_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <iterator>
#include <utility>

#include "orchestrator/build_identity/file_digest.h"
#include "orchestrator/build_identity/revision.h"

namespace slamsweep::orchestrator::inline store {

evaluator::ValidityRun ToValidityRun(const RunRecord& run) {
  evaluator::ValidityRun out;
  out.run_id = run.run_id;
  out.sequence = run.sequence;
  out.noise = run.noise;
  out.algorithm = run.algorithm;
  out.ok = run.status == RunStatus::kOk;
  out.odometry_is_reference = run.odometry_is_reference;
  for (const FlatMetric& metric : run.metrics) {
    if (metric.value) out.values[metric.metric + "." + metric.statistic] = *metric.value;
  }
  if (!run.command.empty()) {
    for (const auto& [key, value] :
         {std::pair{"wall_s", run.wall_s}, {"cpu_s", run.cpu_s}, {"peak_rss_kb", run.peak_rss_kb}}) {
      if (value) out.values[key] = *value;
    }
  }
  return out;
}

std::vector<evaluator::ValidityRun> ToValidityRuns(const std::vector<RunRecord>& runs) {
  std::vector<evaluator::ValidityRun> converted;
  converted.reserve(runs.size());
  for (const RunRecord& run : runs) converted.push_back(ToValidityRun(run));
  return converted;
}

DigestedValidityStudy ValidityStudyOf(const std::vector<RunRecord>& runs) {
  std::vector<evaluator::ValidityRun> inputs = ToValidityRuns(runs);
  DigestedValidityStudy out;
  out.inputs_sha256 = ValidityInputsDigest(inputs);
  out.study = evaluator::ComputeValidityStudy(std::move(inputs));
  return out;
}

namespace {

// The program's own bytes, once per process: a study is only taken from a file the same program wrote.
const std::string& ProgramDigest() {
  static const std::string digest = [] {
    try {
      return Sha256OfFile("/proc/self/exe");
    } catch (const std::exception&) {
      return std::string("unknown program");  // then no digest written here matches one written elsewhere
    }
  }();
  return digest;
}

}  // namespace

std::string ValidityInputsDigest(const std::vector<evaluator::ValidityRun>& runs) {
  std::vector<const evaluator::ValidityRun*> ordered;
  ordered.reserve(runs.size());
  for (const evaluator::ValidityRun& run : runs) ordered.push_back(&run);
  std::stable_sort(
      ordered.begin(), ordered.end(),
      [](const evaluator::ValidityRun* a, const evaluator::ValidityRun* b) { return a->run_id < b->run_id; });
  const evaluator::ValidityOptions options;  // the ones ValidityStudyOf uses
  fmt::memory_buffer text;
  // Fields are separated by characters no run id, name or key holds (tab, newline) and numbers are
  // hexadecimal floats: bit for bit.
  fmt::format_to(std::back_inserter(text), "slamsweep validity inputs 1\n{}\n{}\n{} {} {:a} {:a} {}\n",
                 SlamsweepRevision(), ProgramDigest(), options.min_runs, options.bootstrap.resamples,
                 options.bootstrap.confidence, options.bootstrap.min_defined_fraction, options.bootstrap.seed);
  for (const evaluator::ValidityRun* run : ordered) {
    fmt::format_to(std::back_inserter(text), "{}\t{}\t{}\t{}\t{:d}\t{:d}\n", run->run_id, run->sequence, run->noise,
                   run->algorithm, run->ok, run->odometry_is_reference);
    for (const auto& [key, value] : run->values) fmt::format_to(std::back_inserter(text), "\t{}\t{:a}\n", key, value);
  }
  return Sha256OfBytes(std::string_view(text.data(), text.size()));
}

std::optional<evaluator::ValidityStudy> StoredValidityStudyFor(const nlohmann::json& validity,
                                                               const std::vector<evaluator::ValidityRun>& runs) {
  if (!validity.is_object()) return std::nullopt;
  const auto digest = validity.find("inputs_sha256");
  if (digest == validity.end() || !digest->is_string()) return std::nullopt;
  if (digest->get<std::string>() != ValidityInputsDigest(runs)) return std::nullopt;
  return evaluator::ValidityStudyFromJson(validity);
}

}  // namespace slamsweep::orchestrator::inline store
