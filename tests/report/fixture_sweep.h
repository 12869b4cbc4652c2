#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace slamsweep::report::testing {

/// One run of a synthetic sweep. Metrics left empty are not written (as for a sequence without
/// reference, where the worker computes no ATE).
struct FixtureRun {
  std::string algorithm = "icp-slam";
  std::string adapter = "generic";  ///< run.json's algorithm.adapter ("odometry" makes the baseline row)
  /// run.json's "build" block (slamsweep_revision, program_files); null: not written.
  nlohmann::json build = nullptr;
  /// run.json's group.odometry ("" leaves it out, as run.json did before the odometry mode).
  std::string odometry;
  std::string sequence = "intel";
  std::string noise = "clean";
  int iteration = 0;
  bool ok = true;
  std::string failure_kind = "exit_code";    ///< used when !ok
  std::string reason = "killed by SIGSEGV";  ///< used when !ok
  bool with_reference = true;                ///< reference.tum written (and the ATE, when ape_rmse_m is set)
  /// run.json's sequence.ground_truth ("exact", "corrected_poses", ...); "" writes the fixture's placeholder.
  std::string ground_truth;
  /// run.json's sequence.relations (the relations file: logs of one run share it); "" leaves it out.
  std::string relations_file;
  /// result.json's sequence record: scans and span_s (the scan rate); 0 leaves them out.
  std::size_t scans = 0;
  double span_s = 0.0;
  std::optional<double> ape_rmse_m;
  /// The relations metric (mean, and the counts the worker writes: n, not_covered, outside_log).
  std::optional<double> relations_mean_m;
  std::size_t relations_used = 0;
  std::size_t relations_not_covered = 0;
  std::size_t relations_outside_log = 0;
  std::optional<double> occupied_ratio;
  std::optional<double> corners;
  std::optional<double> enclosed_areas;
  std::optional<double> map_chamfer_m;  ///< map versus reference (written with the other map_compare scores)
  /// With map_chamfer_m: result.json's map_compare details as the worker writes them (scores, the placement
  /// transform, the thresholds and the reference map file, reference_maps/<sequence>.yaml: the room unshifted).
  bool map_compare_details = false;
  /// The map's moved wall (RoomGrid); -1: iteration % 3.
  int room_shift = -1;
  std::string log = "scan 1\nscan 2\n";
  int stages = 3;
  /// map.geojson written, as workers did before the report traced it from the map.
  bool vector_map = true;
  /// Folder name; empty -> made from algorithm, sequence, parameters and iteration like the orchestrator does.
  std::string run_id;
  /// run.json's algorithm.parameters (and group.parameters as "k=v;..."): rows of one algorithm differ in them.
  nlohmann::json parameters = nlohmann::json::object();
  /// Segment RPE at these lengths (ok runs with a reference): metric_details.segment_rpe, the flat
  /// segment_drift_<L>m mean and rpe_segments.csv with 20 segments per length around `segment_drift_pct`.
  std::vector<double> segment_lengths_m;
  double segment_drift_pct = 1.0;
  /// result.json's sequence.scan_spacing block as written; null: left out, as by workers before the block.
  nlohmann::json scan_spacing = nullptr;
};

/// A sweep shaped like configs/paper.yaml for the verdict across data sets: relations on intel-full-rate (dense)
/// and intel-dense (the same run, sparse), relations on fr079, ATE against exact ground truth on simulated-floor,
/// ATE against a corrected log on mit-csail; five contestants, the odometry baseline, and rbpf-slam with a
/// failed run on fr079. The values are in fixture_sweep.cc with the ranks worked out by hand.
std::vector<FixtureRun> PaperLikeFixtureRuns();

/// A successful run of `algorithm` on `sequence` with no metric yet.
FixtureRun MakeRun(std::string algorithm, std::string sequence, int iteration);

/// The run id the orchestrator would give (readable parts reduced to [A-Za-z0-9_.-]).
std::string FixtureRunId(const FixtureRun& run);

/// Writes a sweep output directory following orchestrator/DESIGN.md: summary.json and, per run,
/// runs/<id>/{run.json, result.json, command.txt, log.txt} and for successful runs
/// map.pgm + map.yaml (the evaluator's map_server writer), trajectory.tum, reference.tum,
/// map.geojson and stages/stage_NNNN.png (8-bit grey 0/254/205).
void WriteFixtureSweep(const std::filesystem::path& dir, const std::vector<FixtureRun>& runs);

/// A sweep that exercises every case the report must render: algorithms "gmapping" and a hostile
/// "<script>alert(1)</script>", 3 iterations each on "intel" (with reference) and "mit-no-ref"
/// (without: no ATE), one failed run, an algorithm "single" with one iteration, and a log that
/// contains HTML.
std::vector<FixtureRun> StandardFixtureRuns();

/// A sweep for the validity page: "icp-slam" on "intel" and "floor", noise settings "odo-1",
/// "odo-2", "odo-10" (natural order) x 3 iterations. ATE and Chamfer rise with the noise level
/// and the iteration; corners rise exactly with the ATE on both sequences (rho = +1 everywhere),
/// the occupied ratio falls exactly with it (rho = -1), enclosed areas are constant (no variation).
std::vector<FixtureRun> ValidityFixtureRuns();

/// StandardFixtureRuns with result.json's sequence.scan_spacing: on "intel" its 910 keyframes as `slamsweep data
/// info intel` measures them, rounded (909 steps; gap 3.31 / 4.89 s, travel 0.67 / 1.05 m, rotation 0.39 /
/// 0.57 rad, median / p95: too far apart for scan matching); on "mit-no-ref" 5 cm per scan (dense enough).
std::vector<FixtureRun> DensityFixtureRuns();

/// A sweep for the segment-length and parameter pages on "intel" (reference) and "mit-no-ref": gmapping
/// and hector with segment RPE at 10, 20 and 30 m (hector drifting twice as much), "icp-slam" swept
/// over ICP.maxIterations (20, 40, 80; 40 is best), "rbpf-slam" over particles x resample (2 x 2), 2-3
/// iterations each, and a hostile algorithm name.
std::vector<FixtureRun> ViewsFixtureRuns();

/// A sweep for "Maps compared": on "intel" (reference trajectory and reference map) gmapping (3 iterations,
/// its map close to the reference) and hector (3 iterations, a wall 6 cells off, placed 0.2 m off), each with
/// map_compare details; on "mit-no-ref" gmapping without any reference.
std::vector<FixtureRun> MapsFixtureRuns();

}  // namespace slamsweep::report::testing
