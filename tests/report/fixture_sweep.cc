#include "tests/report/fixture_sweep.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "evaluator/core/occupancy_grid.h"
#include "evaluator/core/pose.h"
#include "evaluator/core/trajectory.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/formats/trajectory/tum_format.h"

namespace slamsweep::report::testing {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
namespace ev = slamsweep::evaluator;

std::string Readable(const std::string& text) {
  std::string out;
  for (char c : text)
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-') ? c : '_';
  while (!out.empty() && out.front() == '.') out.erase(0, 1);
  return out.substr(0, 32);
}

void Write(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// A 40 x 30 room (walls occupied, inside free, a margin unknown); `shift` moves one wall so
// iterations differ a little.
ev::OccupancyGrid RoomGrid(int shift) {
  ev::OccupancyGrid grid(40, 30, 0.1, {-2.0, -1.5, 0.0});
  for (int row = 3; row < 27; ++row) {
    for (int col = 3; col < 37 - shift; ++col) {
      const bool wall = row == 3 || row == 26 || col == 3 || col == 36 - shift;
      grid.at(row, col) = wall ? 1.0f : 0.0f;
    }
  }
  return grid;
}

ev::Trajectory Circle(double radius_m, double noise_m) {
  ev::Trajectory trajectory;
  for (int i = 0; i < 20; ++i) {
    const double angle = 2.0 * M_PI * i / 20.0;
    const double wobble = noise_m * std::sin(3.0 * angle);
    trajectory.Add(100.0 + i * 0.5, ev::Pose::Planar((radius_m + wobble) * std::cos(angle),
                                                     (radius_m + wobble) * std::sin(angle), angle + M_PI / 2));
  }
  return trajectory;
}

json Metric(const std::string& name, const char* statistic, double value, const char* unit) {
  return {{"metric", name}, {"statistic", statistic}, {"value", value}, {"unit", unit}};
}

/// The segment RPE a worker would record (orchestrator/worker/run_metrics.cc): details, the flat mean
/// drift per length and rpe_segments.csv with 20 segments spread evenly over +-50 % of the drift.
void WriteSegments(const FixtureRun& run, const fs::path& run_dir, json& metrics, json& details) {
  json lengths = json::array();
  std::string csv = "length_m,start_s,end_s,translation_m,translation_pct,rotation_deg_per_m\n";
  for (const double length : run.segment_lengths_m) {
    const double drift = run.segment_drift_pct * (1.0 + 0.01 * length) + 0.05 * run.iteration;
    for (int k = 0; k < 20; ++k) {
      const double pct = drift * (0.5 + k / 19.0);
      csv += fmt::format("{},{},{},{},{},{}\n", length, 100 + k, 110 + k, pct * length / 100.0, pct, 0.02 * pct);
    }
    lengths.push_back({{"length_m", length},
                       {"n", 20},
                       {"translation_m", {{"mean", drift * length / 100.0}}},
                       {"translation_pct", {{"mean", drift}}},
                       {"rotation_deg_per_m", {{"mean", 0.02 * drift}}}});
    metrics.push_back(Metric(fmt::format("segment_drift_{}m", length), "mean", drift, "%"));
  }
  details["segment_rpe"] = {{"specification",
                             {{"lengths_m", run.segment_lengths_m},
                              {"lengths_from", "reference path"},
                              {"reference_path_m", 100.0},
                              {"pairs_from", "reference"}}},
                            {"lengths", lengths}};
  Write(run_dir / "rpe_segments.csv", csv);
}

/// "k=v;..." as orchestrator/matrix ParametersText writes it (sorted by name: nlohmann's order).
std::string ParametersTextOf(const json& parameters) {
  std::string text;
  for (const auto& [name, value] : parameters.items()) {
    if (!text.empty()) text += ';';
    text += name + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  }
  return text;
}

/// metric_details.map_compare as orchestrator/worker/run_metrics.cc writes it, against
/// reference_maps/<sequence>.yaml (written here once: the room with no wall moved).
json MapCompareDetails(const FixtureRun& run, const fs::path& dir) {
  const fs::path reference = dir / "reference_maps" / (Readable(run.sequence) + ".yaml");
  if (!fs::exists(reference)) {
    fs::create_directories(reference.parent_path());
    ev::WriteMapServer(RoomGrid(0), reference);
  }
  const double chamfer = *run.map_chamfer_m;
  return {
      {"chamfer_m", chamfer},
      {"f1", 1.0 / (1.0 + chamfer)},
      {"accuracy", 1.0 / (1.0 + 0.5 * chamfer)},
      {"completeness", 1.0 / (1.0 + 2.0 * chamfer)},
      {"iou_occupied", 0.5},
      {"iou_free", 0.9},
      {"placement", "ATE alignment"},
      {"transform", {{"x_m", 2.0 * chamfer}, {"y_m", 0.0}, {"yaw_rad", 0.0}}},
      {"specification",
       {{"occupied_threshold", 0.65}, {"free_threshold", 0.196}, {"match_radius_cells", 1}, {"alignment", "given"}}},
      {"reference_map", {{"file", fs::absolute(reference).string()}, {"source", "rendered"}, {"resolution_m", 0.1}}}};
}

}  // namespace

FixtureRun MakeRun(std::string algorithm, std::string sequence, int iteration) {
  FixtureRun run;
  run.algorithm = std::move(algorithm);
  run.sequence = std::move(sequence);
  run.iteration = iteration;
  return run;
}

std::string FixtureRunId(const FixtureRun& run) {
  if (!run.run_id.empty()) return run.run_id;
  const std::string parameters = run.parameters.empty() ? "" : "-" + Readable(ParametersTextOf(run.parameters));
  return Readable(run.algorithm) + parameters + "-" + Readable(run.sequence) + "-" + Readable(run.noise) + "-i" +
         std::to_string(run.iteration) + "-0000abcd";
}

void WriteFixtureSweep(const fs::path& dir, const std::vector<FixtureRun>& runs) {
  json summary = {{"sweep", "fixture"}, {"runs", json::array()}};
  for (const FixtureRun& run : runs) {
    const std::string id = FixtureRunId(run);
    const fs::path run_dir = dir / "runs" / id;
    fs::create_directories(run_dir);
    const json spec = {
        {"run_id", id},
        {"sweep", "fixture"},
        {"algorithm",
         {{"name", run.algorithm},
          {"adapter", run.adapter},
          {"parameters", run.parameters},
          {"timeout_s", 300},
          {"memory_limit_mb", 4096},
          {"command", nullptr}}},
        {"group",
         {{"sequence", run.sequence},
          {"algorithm", run.algorithm},
          {"parameters", ParametersTextOf(run.parameters)},
          {"noise", run.noise}}},
        {"sequence",
         {{"name", run.sequence},
          {"format", "carmen"},
          {"path", "/data/" + run.sequence + ".clf"},
          {"ground_truth", !run.ground_truth.empty() ? run.ground_truth
                           : run.with_reference      ? "reference.tum"
                                                     : "none"}}},
        {"noise", {{"name", run.noise}, {"odometry", nullptr}, {"range", nullptr}}},
        {"iteration", run.iteration},
        {"seed", 1000 + run.iteration},
        {"evaluation", {{"align", "se2"}, {"rpe_delta_m", 1.0}, {"t_max_diff_s", 0.01}, {"stages", run.stages}}},
        {"thresholds", json::array()}};
    json written = spec;
    if (!run.build.is_null()) written["build"] = run.build;
    if (!run.odometry.empty()) written["group"]["odometry"] = run.odometry;
    if (!run.relations_file.empty()) written["sequence"]["relations"] = run.relations_file;
    Write(run_dir / "run.json", written.dump(2));
    Write(run_dir / "command.txt", "fake-slam\n--input\ninput/log.clf\n");
    Write(run_dir / "log.txt", run.log);

    json result = {{"run_id", id},
                   {"status", run.ok ? "ok" : "failed"},
                   {"failure_kind", run.ok ? json(nullptr) : json(run.failure_kind)},
                   {"reason", run.ok ? "" : run.reason},
                   {"exit_code", run.ok ? 0 : 139},
                   {"signal", nullptr},
                   {"wall_s", 3.25 + run.iteration},
                   {"cpu_s", 3.0 + run.iteration},
                   {"peak_rss_kb", 81234},
                   {"started_at", "2026-11-22T05:00:00Z"},
                   {"finished_at", "2026-11-22T05:00:03Z"},
                   {"command", {"fake-slam", "--input", "input/log.clf"}},
                   {"warnings", json::array()}};
    if (run.scans > 0) result["sequence"] = {{"scans", run.scans}, {"span_s", run.span_s}};
    json metrics = json::array();
    json details = json::object();
    json outputs = {{"log", "log.txt"}};
    if (run.ok) {
      ev::WriteMapServer(RoomGrid(run.room_shift >= 0 ? run.room_shift : run.iteration % 3), run_dir / "map.yaml");
      ev::WriteTum(Circle(1.0, 0.02 * (run.iteration + 1)), run_dir / "trajectory.tum");
      outputs["map"] = "map.yaml";
      outputs["trajectory"] = "trajectory.tum";
      if (run.vector_map) {
        Write(run_dir / "map.geojson", R"({"type": "FeatureCollection", "features": []})");
        outputs["vector_map"] = "map.geojson";
      }
      if (run.with_reference) {
        ev::WriteTum(Circle(1.0, 0.0), run_dir / "reference.tum");
        outputs["reference"] = "reference.tum";
      }
      fs::create_directories(run_dir / "stages");
      json stages = json::array();
      for (int s = 0; s < run.stages; ++s) {
        cv::Mat image(30, 40, CV_8UC1, cv::Scalar(205));
        cv::rectangle(image, cv::Rect(3, 3, 4 + (30 * (s + 1)) / run.stages, 24), cv::Scalar(254), cv::FILLED);
        cv::rectangle(image, cv::Rect(3, 3, 4 + (30 * (s + 1)) / run.stages, 24), cv::Scalar(0), 1);
        char name[32];
        std::snprintf(name, sizeof name, "stages/stage_%04d.png", s);
        cv::imwrite((run_dir / name).string(), image);
        stages.push_back(name);
      }
      outputs["stages"] = stages;
      if (run.ape_rmse_m) {
        metrics.push_back(Metric("ape_trans", "rmse", *run.ape_rmse_m, "m"));
        metrics.push_back(Metric("ape_trans", "mean", *run.ape_rmse_m * 0.9, "m"));
        details["ape_trans"] = {{"metric", "ape"},
                                {"unit", "m"},
                                {"rmse", *run.ape_rmse_m},
                                {"specification", {{"pose_relation", "translation_part"}, {"alignment", "se2"}}}};
      }
      if (run.relations_mean_m) {
        metrics.push_back(Metric("relations_trans", "mean", *run.relations_mean_m, "m"));
        metrics.push_back(Metric("relations_trans", "n", static_cast<double>(run.relations_used), "count"));
        metrics.push_back(
            Metric("relations_trans", "not_covered", static_cast<double>(run.relations_not_covered), "count"));
        metrics.push_back(
            Metric("relations_trans", "outside_log", static_cast<double>(run.relations_outside_log), "count"));
      }
      if (run.occupied_ratio)
        metrics.push_back(Metric("occupied_to_free_unknown", "value", *run.occupied_ratio, "ratio"));
      if (run.corners) metrics.push_back(Metric("corners", "value", *run.corners, "count"));
      if (run.with_reference && !run.segment_lengths_m.empty()) {
        WriteSegments(run, run_dir, metrics, details);
        outputs["rpe_segments"] = "rpe_segments.csv";
      }
      if (run.enclosed_areas) metrics.push_back(Metric("enclosed_areas", "value", *run.enclosed_areas, "count"));
      if (run.map_chamfer_m) {
        metrics.push_back(Metric("map_chamfer", "value", *run.map_chamfer_m, "m"));
        metrics.push_back(Metric("map_f1", "value", 1.0 / (1.0 + *run.map_chamfer_m), "ratio"));
        if (run.map_compare_details) details["map_compare"] = MapCompareDetails(run, dir);
      }
    }
    if (!run.scan_spacing.is_null()) result["sequence"]["scan_spacing"] = run.scan_spacing;
    result["outputs"] = outputs;
    result["metrics"] = metrics;
    result["metric_details"] = details;
    Write(run_dir / "result.json", result.dump(2));
    summary["runs"].push_back({{"run_id", id},
                               {"algorithm", run.algorithm},
                               {"sequence", run.sequence},
                               {"status", result["status"]},
                               {"metrics", metrics}});
  }
  Write(dir / "summary.json", summary.dump(2));
  // Stand-ins for the orchestrator's tables (orchestrator/store/csv_tables.h): the report copies them.
  Write(dir / "summary.csv", "sequence,algorithm,parameters,noise,n_runs,n_ok\nintel,gmapping,,clean,3,3\n");
  Write(dir / "runs.csv", "run_id,sequence,algorithm\n" + std::to_string(runs.size()) + " runs\n");
}

std::vector<FixtureRun> StandardFixtureRuns() {
  std::vector<FixtureRun> runs;
  const std::string hostile = "<script>alert(1)</script>";
  for (int i = 0; i < 3; ++i) {
    FixtureRun a = MakeRun("gmapping", "intel", i);
    a.ape_rmse_m = 0.10 + 0.01 * i;  // 0.10 0.11 0.12: mean 0.11, std 0.01
    a.occupied_ratio = 0.05;
    a.corners = 10.0 + i;
    a.enclosed_areas = 1.0;
    runs.push_back(a);
    FixtureRun b = MakeRun(hostile, "intel", i);
    b.ape_rmse_m = 0.2 + 0.1 * i;  // 0.2 0.3 0.4: mean 0.3, std 0.1
    b.occupied_ratio = 0.04;       // best occupied ratio
    b.corners = 20.0;
    b.enclosed_areas = 2.0;
    b.log = "<b>bold</b> & <img src=x onerror=alert(2)>\n";
    if (i == 2) b.ok = false;  // one failed run: b has 2 values, 0.2 and 0.3
    runs.push_back(b);
    FixtureRun c = MakeRun("gmapping", "mit-no-ref", i);
    c.with_reference = false;
    c.occupied_ratio = 0.07;
    c.corners = 30.0 - i;  // 30 29 28: median run = iteration 1
    c.enclosed_areas = 0.0;
    runs.push_back(c);
  }
  FixtureRun single = MakeRun("single", "intel", 0);
  single.ape_rmse_m = 0.5;
  single.occupied_ratio = 0.06;
  single.corners = 12.0;
  single.enclosed_areas = 1.0;
  runs.push_back(single);
  return runs;
}

std::vector<FixtureRun> PaperLikeFixtureRuns() {
  // Means per data set (three iterations v - 0.001, v, v + 0.001 for the seeded, one for the others):
  //                  intel-full-rate  fr079  simulated-floor      ranks            mean rank
  //   cartographer        0.04        0.05       0.12             1   1    2        4/3
  //   gmapping            0.05        0.06       0.10             2   2.5  1        5.5/3
  //   vinyslam            0.07        0.06       0.20             3   2.5  3        8.5/3
  //   tinyslam            0.09        0.10       0.30             4   4    4        4
  //   hector              0.20        0.30       0.50             5   5    5        5
  // intel-dense is the same run as intel-full-rate at 1 scan/s against 7.35 (hector best there: it must not
  // count); mit-csail is scored by ATE against its corrected log only (it must not count either).
  struct Row {
    const char* algorithm;
    int iterations;
    double full_rate, dense, fr079, floor, csail;
  };
  const Row rows[] = {{"cartographer", 1, 0.04, 0.30, 0.05, 0.12, 0.5}, {"gmapping", 3, 0.05, 0.20, 0.06, 0.10, 0.4},
                      {"vinyslam", 3, 0.07, 0.25, 0.06, 0.20, 0.3},     {"tinyslam", 3, 0.09, 0.15, 0.10, 0.30, 0.2},
                      {"hector", 1, 0.20, 0.01, 0.30, 0.50, 0.1},       {"rbpf-slam", 3, 0.06, 0.10, 0.07, 0.15, 0.6},
                      {"odometry", 1, 1.50, 1.50, 2.00, 3.00, 4.0}};
  std::vector<FixtureRun> runs;
  for (const Row& row : rows) {
    for (int i = 0; i < row.iterations; ++i) {
      const double jitter = row.iterations == 1 ? 0.0 : 0.001 * (i - 1);
      const auto make = [&](const char* sequence) {
        FixtureRun run = MakeRun(row.algorithm, sequence, i);
        if (std::string(row.algorithm) == "odometry") run.adapter = "odometry";
        return run;
      };
      FixtureRun full_rate = make("intel-full-rate");
      full_rate.ground_truth = "relations_only";
      full_rate.with_reference = false;
      full_rate.relations_file = "/data/intel/intel.relations";
      full_rate.relations_mean_m = row.full_rate + jitter;
      full_rate.relations_used = 1033;
      full_rate.scans = 8000;
      full_rate.span_s = 1088.6;
      runs.push_back(full_rate);
      FixtureRun dense = make("intel-dense");
      dense.ground_truth = "corrected_poses";
      dense.relations_file = "/data/intel/intel.relations";
      dense.ape_rmse_m = 2.0 * (row.dense + jitter);
      dense.relations_mean_m = row.dense + jitter;
      dense.relations_used = 1800;
      dense.scans = 1089;
      dense.span_s = 1088.6;
      runs.push_back(dense);
      FixtureRun fr079 = make("fr079");
      fr079.ground_truth = "corrected_poses";
      fr079.relations_file = "/data/fr079/fr079.relations";
      fr079.ape_rmse_m = 2.0 * (row.fr079 + jitter);
      fr079.relations_mean_m = row.fr079 + jitter;
      fr079.relations_used = 500;
      if (std::string(row.algorithm) == "rbpf-slam" && i == 2) fr079.ok = false;
      runs.push_back(fr079);
      FixtureRun floor = make("simulated-floor");
      floor.ground_truth = "exact";
      floor.ape_rmse_m = row.floor + jitter;
      runs.push_back(floor);
      FixtureRun csail = make("mit-csail");
      csail.ground_truth = "corrected_poses";
      csail.ape_rmse_m = row.csail + jitter;
      runs.push_back(csail);
    }
  }
  return runs;
}

std::vector<FixtureRun> DensityFixtureRuns() {
  const json keyframes = {{"steps", 909},
                          {"gap_s", {{"median", 3.31}, {"p95", 4.89}}},
                          {"travel_m", {{"median", 0.67}, {"p95", 1.05}}},
                          {"rotation_rad", {{"median", 0.39}, {"p95", 0.57}}},
                          {"odometry_moves", true}};
  const json dense = {{"steps", 2724},
                      {"gap_s", {{"median", 0.2}, {"p95", 0.5}}},
                      {"travel_m", {{"median", 0.05}, {"p95", 0.12}}},
                      {"rotation_rad", {{"median", 0.02}, {"p95", 0.1}}},
                      {"odometry_moves", true}};
  std::vector<FixtureRun> runs = StandardFixtureRuns();
  for (FixtureRun& run : runs) run.scan_spacing = run.sequence == "intel" ? keyframes : dense;
  return runs;
}

std::vector<FixtureRun> ValidityFixtureRuns() {
  std::vector<FixtureRun> runs;
  const std::pair<const char*, double> levels[] = {{"odo-1", 1.0}, {"odo-2", 2.0}, {"odo-10", 10.0}};
  for (const char* sequence : {"intel", "floor"}) {
    const double scale = std::string(sequence) == "intel" ? 1.0 : 0.1;
    for (const auto& [noise, level] : levels) {
      for (int i = 0; i < 3; ++i) {
        FixtureRun run = MakeRun("icp-slam", sequence, i);
        run.noise = noise;
        const double ate = scale * (0.1 * level + 0.01 * i);
        run.ape_rmse_m = ate;
        run.map_chamfer_m = 0.5 * ate;
        run.corners = 100.0 * ate / scale;
        run.occupied_ratio = 0.5 - ate / scale / 5.0;
        run.enclosed_areas = 2.0;
        runs.push_back(run);
      }
    }
  }
  return runs;
}

std::vector<FixtureRun> ViewsFixtureRuns() {
  std::vector<FixtureRun> runs;
  const auto add = [&](const std::string& algorithm, const json& parameters, int iterations, double ape_m,
                       double drift_pct) {
    for (int i = 0; i < iterations; ++i) {
      FixtureRun run = MakeRun(algorithm, "intel", i);
      run.parameters = parameters;
      run.ape_rmse_m = ape_m + 0.01 * i;
      run.occupied_ratio = 0.05 + 0.001 * i;
      run.corners = 10.0 + i + 10.0 * ape_m;
      run.enclosed_areas = 1.0;
      run.segment_lengths_m = {10, 20, 30};
      run.segment_drift_pct = drift_pct;
      runs.push_back(run);
    }
  };
  add("gmapping", json::object(), 3, 0.10, 1.5);
  add("hector", json::object(), 3, 0.30, 3.0);
  add("<b>odd & name</b>", json::object(), 2, 0.25, 2.0);
  for (const auto& [iterations, ape] : {std::pair<int, double>{20, 0.40}, {40, 0.12}, {80, 0.20}}) {
    add("icp-slam", json{{"ICP.maxIterations", iterations}, {"ICP.thresholdDist", 0.75}}, 2, ape, 1.0 + ape * 5);
  }
  for (const int particles : {10, 30}) {
    for (const double resample : {0.5, 1.0}) {
      add("rbpf-slam", json{{"particles", particles}, {"resample", resample}}, 2, 0.5 / particles + 0.1 * resample,
          2.0 + resample);
    }
  }
  FixtureRun no_reference = MakeRun("gmapping", "mit-no-ref", 0);
  no_reference.with_reference = false;
  no_reference.corners = 30.0;
  no_reference.occupied_ratio = 0.07;
  runs.push_back(no_reference);
  return runs;
}

std::vector<FixtureRun> MapsFixtureRuns() {
  std::vector<FixtureRun> runs;
  for (int i = 0; i < 3; ++i) {
    FixtureRun close = MakeRun("gmapping", "intel", i);
    close.ape_rmse_m = 0.05 + 0.01 * i;
    close.map_chamfer_m = 0.02 + 0.01 * i;
    close.room_shift = i % 2;
    close.map_compare_details = true;
    runs.push_back(close);
    FixtureRun off = MakeRun("hector", "intel", i);
    off.ape_rmse_m = 0.3 + 0.1 * i;
    off.map_chamfer_m = 0.1;  // placed 0.2 m off by the transform
    off.room_shift = 6;
    off.map_compare_details = true;
    runs.push_back(off);
    FixtureRun no_reference = MakeRun("gmapping", "mit-no-ref", i);
    no_reference.with_reference = false;
    no_reference.corners = 30.0 - i;
    runs.push_back(no_reference);
  }
  return runs;
}

}  // namespace slamsweep::report::testing
