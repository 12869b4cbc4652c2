#include "orchestrator/adapters/run_inputs.h"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "evaluator/core/input_error.h"
#include "evaluator/noise/odometry_noise.h"
#include "evaluator/noise/random.h"
#include "evaluator/noise/range_noise.h"
#include "evaluator/catalog/catalog.h"
#include "evaluator/sequence/scan_spacing.h"
#include "evaluator/sequence/sequence_cut.h"
#include "orchestrator/input_cache/prepared_sequence_cache.h"

namespace slamsweep::orchestrator::inline adapters {

namespace ev = slamsweep::evaluator;

ev::Sequence CutSequence(ev::Sequence sequence, std::size_t max_scans) {
  if (max_scans == 0) throw ev::InputError("sequence.max_scans: expected a positive number of scans, got 0");
  return ev::KeepScanRange(std::move(sequence), 0, max_scans);
}

nlohmann::json ApplyRunNoise(ev::Sequence& sequence, const NoiseSpec& noise, std::uint64_t seed) {
  nlohmann::json record;
  record["name"] = noise.name;
  record["seed"] = seed;
  record["odometry"] = nullptr;
  record["range"] = nullptr;
  if (noise.odometry && *noise.odometry != ev::OdometryNoise{}) {
    ev::ValidateOdometryNoise(*noise.odometry);
    // Noise drawn around the odometry of a corrected log in reference mode would be drawn around its
    // reference anyway (they are equal); drawing around the truth keeps the run's truth exact. On
    // recorded odometry the noise comes on top of what the robot measured.
    const bool around_reference = ev::OdometryEqualsReference(sequence);
    const ev::Trajectory clean = around_reference ? *sequence.reference : sequence.odometry;
    const std::uint64_t odometry_seed = ev::DeriveSeed(seed, 0);
    sequence.odometry = ev::ApplyOdometryNoise(clean, *noise.odometry, odometry_seed);
    if (!sequence.odometry_readings.empty()) {
      sequence.odometry_readings = ev::NoisyReadings(sequence.odometry_readings, clean, sequence.odometry);
    }
    record["odometry"] = *noise.odometry;
    record["odometry_seed"] = odometry_seed;
    record["odometry_around"] = around_reference ? "reference" : "odometry";
  }
  if (noise.range && *noise.range != ev::RangeNoise{}) {
    ev::ValidateRangeNoise(*noise.range);
    const std::uint64_t range_seed = ev::DeriveSeed(seed, 1);
    sequence.scans = ev::ApplyRangeNoise(sequence.scans, *noise.range, range_seed);
    record["range"] = *noise.range;
    record["range_seed"] = range_seed;
  }
  return record;
}

bool OdometryIsReference(const ev::Sequence& sequence) { return ev::OdometryEqualsReference(sequence); }

ev::Sequence LoadRunSequence(const RunSpec& spec) {
  // run.json holds resolved paths: no ${VARIABLE} is left to expand.
  ev::Sequence sequence = ev::LoadCatalogSequence(spec.sequence.entry, {});
  if (spec.sequence.max_scans) sequence = CutSequence(std::move(sequence), *spec.sequence.max_scans);
  ev::ValidateSequence(sequence);
  return sequence;
}

RunInputs PrepareRunInputs(const RunSpec& spec, const std::filesystem::path& cache_dir) {
  const auto prepare = [&spec] { return LoadRunSequence(spec); };
  std::string cache_problem;
  ev::Sequence sequence;
  if (cache_dir.empty()) {
    sequence = prepare();
  } else {
    PreparedSequence prepared = LoadOrPrepareSequence(spec, cache_dir, prepare);
    sequence = std::move(prepared.sequence);
    cache_problem = std::move(prepared.cache_problem);
  }
  RunInputs inputs;
  if (const std::optional<ev::ScanSpacing> spacing = ev::ComputeScanSpacing(sequence)) {
    inputs.sequence_record["scan_spacing"] = ev::ScanSpacingJson(*spacing);
  }
  inputs.noise_record = ApplyRunNoise(sequence, spec.noise, spec.seed);
  inputs.odometry_is_reference = OdometryIsReference(sequence);
  inputs.warnings = std::move(sequence.warnings);
  if (!cache_problem.empty()) inputs.warnings.push_back("prepared inputs not cached: " + cache_problem);
  inputs.truth.reference = std::move(sequence.reference);
  inputs.truth.relations = std::move(sequence.relations);
  inputs.truth.relations_outside_log = sequence.relations_outside_log;
  inputs.sequence_record["scans"] = sequence.scans.size();
  if (!sequence.scans.empty()) {
    inputs.sequence_record["span_s"] = sequence.scans.back().stamp_s - sequence.scans.front().stamp_s;
  }
  if (sequence.stamp_facts) inputs.sequence_record["stamps"] = ev::StampFactsJson(*sequence.stamp_facts);
  inputs.robot = ev::TakeRobotLog(sequence);
  return inputs;
}

}  // namespace slamsweep::orchestrator::inline adapters
