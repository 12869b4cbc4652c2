#include "orchestrator/worker/run_metrics.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <optional>

#include "evaluator/core/input_error.h"
#include "orchestrator/run/run_failure.h"
#include "evaluator/map_metrics/paper_metrics.h"
#include "evaluator/map_compare/map_compare.h"
#include "evaluator/map_compare/map_resample.h"
#include "evaluator/trajectory_metrics/ape.h"
#include "evaluator/trajectory_metrics/relations_metric.h"
#include "evaluator/trajectory_metrics/rpe.h"
#include "evaluator/trajectory_metrics/segment_rpe.h"

namespace slamsweep::orchestrator::inline worker {

namespace ev = slamsweep::evaluator;

namespace {

void AddStatistics(RunMetrics& out, const std::string& name, const ev::MetricResult& result) {
  const ev::ErrorStatistics& s = result.statistics;
  for (const auto& [statistic, value] : {std::pair<const char*, double>{"rmse", s.rmse},
                                         {"mean", s.mean},
                                         {"median", s.median},
                                         {"std", s.std},
                                         {"min", s.min},
                                         {"max", s.max},
                                         {"sse", s.sse},
                                         {"n", static_cast<double>(s.n)}}) {
    out.metrics.push_back({name, statistic, value, statistic == std::string("n") ? "count" : result.unit});
  }
  out.details[name] = result.ToJson();
}

void AddSegmentStatistics(RunMetrics& out, const std::string& name,
                          const std::optional<ev::ErrorStatistics>& statistics, const char* unit) {
  if (!statistics) return;
  const ev::ErrorStatistics& s = *statistics;
  // The mean is the headline (KITTI's drift); no rmse, whose square weighs the worst segments.
  for (const auto& [statistic, value] : {std::pair<const char*, double>{"mean", s.mean},
                                         {"median", s.median},
                                         {"std", s.std},
                                         {"min", s.min},
                                         {"max", s.max},
                                         {"n", static_cast<double>(s.n)}}) {
    out.metrics.push_back({name, statistic, value, statistic == std::string("n") ? "count" : unit});
  }
}

/// The segment RPE at the configured lengths, or at 10-50 % of the reference path: the whole
/// reference of the sequence, never the part this run's estimate covers, so every run of a
/// sequence gets the same lengths.
void AddSegmentRpe(RunMetrics& out, const EvaluationOptions& evaluation, const ev::AssociationOptions& association,
                   const ev::Trajectory& reference, const ev::Trajectory& estimate) {
  const double path_m = ev::PathLengthM(reference);
  const std::vector<double> lengths =
      evaluation.rpe_segments_m ? *evaluation.rpe_segments_m : ev::DefaultSegmentLengthsM(path_m);
  if (lengths.empty()) {
    if (!evaluation.rpe_segments_m) {
      out.warnings.push_back(
          fmt::format("segment_rpe: the reference path ({} m) is too short for segments of 1 m", path_m));
    }
    return;
  }
  ev::SegmentRpeOptions options;
  options.lengths_m = lengths;
  options.association = association;
  options.relative_tolerance = ev::kRpeDeltaTolerance;
  const ev::SegmentRpeResult result = ev::SegmentRpe(options).Compute(reference, estimate);
  std::vector<ev::SegmentErrorRecord> records;
  for (const ev::SegmentLengthResult& segments : result.lengths) {
    if (segments.pairs.empty()) {
      out.warnings.push_back(fmt::format(
          "segment_rpe: no segment of {} m fits in the part of the reference the estimate covers", segments.length_m));
    }
    AddSegmentStatistics(out, SegmentRpeMetricName("trans", segments.length_m), segments.translation_m_statistics, "m");
    AddSegmentStatistics(out, SegmentRpeMetricName("drift", segments.length_m), segments.translation_pct_statistics,
                         "%");
    AddSegmentStatistics(out, SegmentRpeMetricName("rot", segments.length_m), segments.rotation_deg_per_m_statistics,
                         "deg/m");
    for (std::size_t k = 0; k < segments.pairs.size(); ++k) {
      records.push_back({segments.length_m, segments.start_s[k], segments.end_s[k], segments.translation_m[k],
                         segments.translation_pct[k], segments.rotation_deg_per_m[k]});
    }
  }
  nlohmann::json details = result.ToJson();
  details["specification"]["lengths_from"] = evaluation.rpe_segments_m ? "evaluation.rpe_segments_m" : "reference path";
  details["specification"]["reference_path_m"] = path_m;
  out.details["segment_rpe"] = std::move(details);
  out.segment_errors = std::move(records);
}

/// The relations metric's flat numbers; "n" counts the relations used, "not_covered" those inside the
/// log but outside the estimate's time span (coverage = n / (n + not_covered)), "outside_log" those of
/// the relations file that the log (or its cut) does not hold.
void AddRelations(std::vector<FlatMetric>& metrics, const ev::RelationsResult& result, std::size_t outside_log) {
  const double used = static_cast<double>(result.used);
  const double not_covered = static_cast<double>(result.not_covered);
  const double outside = static_cast<double>(outside_log);
  for (const char* name : {"relations_trans", "relations_rot"}) {
    const bool trans = name == std::string_view("relations_trans");
    metrics.push_back(
        {name, "mean", trans ? result.translation_abs_mean_m : result.rotation_abs_mean_deg, trans ? "m" : "deg"});
    metrics.push_back(
        {name, "std", trans ? result.translation_abs_std_m : result.rotation_abs_std_deg, trans ? "m" : "deg"});
    metrics.push_back({name, "n", used, "count"});
    metrics.push_back({name, "not_covered", not_covered, "count"});
    metrics.push_back({name, "outside_log", outside, "count"});
  }
}

/// Runs one metric; an InputError (no pairs, degenerate alignment, empty map) becomes a warning
/// naming the metric, so one metric that cannot be computed does not hide the others.
void Attempt(RunMetrics& out, const std::string& name, const std::function<void()>& compute) {
  try {
    compute();
  } catch (const ev::InputError& error) {
    out.warnings.push_back(name + ": " + error.what());
  }
}

}  // namespace

std::string SegmentRpeMetricName(std::string_view kind, double length_m) {
  std::string length = fmt::format("{}", length_m);
  for (char& c : length) {
    if (c == '.') c = 'p';
  }
  return fmt::format("segment_{}_{}m", kind, length);
}

nlohmann::json RelationsCoverage::ToJson() const {
  return {{"basis", "relations"}, {"fraction", Fraction()}, {"covered", covered}, {"inside_log", inside_log}};
}

void RequireCoverage(const EvaluationOptions& evaluation, const RunMetrics& metrics) {
  if (metrics.relations_coverage && metrics.relations_coverage->Fraction() < evaluation.min_coverage) {
    const RelationsCoverage& c = *metrics.relations_coverage;
    throw RunFailure(FailureKind::kIncompleteTrajectory,
                     fmt::format("the trajectory covers {} of the {} relations inside the log ({:.1f} %), below "
                                 "evaluation.min_coverage {:.0f} %",
                                 c.covered, c.inside_log, 100.0 * c.Fraction(), 100.0 * evaluation.min_coverage));
  }
  if (!metrics.coverage || metrics.coverage->fraction >= evaluation.min_coverage) return;
  const ev::TrajectoryCoverage& c = *metrics.coverage;
  throw RunFailure(FailureKind::kIncompleteTrajectory,
                   fmt::format("the trajectory covers {:.1f} % of the reference's time span ({:.1f} to {:.1f} s of "
                               "{:.1f} to {:.1f} s), below evaluation.min_coverage {:.0f} %",
                               100.0 * c.fraction, c.estimate_start_s, c.estimate_end_s, c.reference_start_s,
                               c.reference_end_s, 100.0 * evaluation.min_coverage));
}

RunMetrics ComputeRunMetrics(const EvaluationOptions& evaluation, const MetricInputs& inputs) {
  ev::AssociationOptions association;
  association.t_max_diff_s = evaluation.t_max_diff_s;
  ev::AlignmentOptions alignment;
  alignment.mode = ev::ParseAlignmentMode(evaluation.align);

  RunMetrics out;
  // The estimate-to-reference transform of the ATE: the map-versus-reference scores place the map with it.
  std::optional<ev::Alignment> ape_alignment;
  if (inputs.estimate && inputs.reference) {
    Attempt(out, "coverage", [&] {
      out.coverage = ev::ComputeCoverage(*inputs.reference, *inputs.estimate);
      out.details["coverage"] = out.coverage->ToJson();
      out.details["coverage"]["min_coverage"] = evaluation.min_coverage;
    });
    for (const auto& [name, relation] :
         {std::pair<const char*, ev::PoseRelation>{"ape_trans", ev::PoseRelation::kTranslation},
          {"ape_rot", ev::PoseRelation::kRotationDeg}}) {
      Attempt(out, name, [&, name = std::string(name), relation = relation] {
        const ev::Ape ape({relation, association, alignment});
        const ev::MetricResult result = ape.Compute(*inputs.reference, *inputs.estimate);
        if (relation == ev::PoseRelation::kTranslation) ape_alignment = result.alignment;
        AddStatistics(out, name, result);
      });
    }
    for (const auto& [name, relation] :
         {std::pair<const char*, ev::PoseRelation>{"rpe_trans", ev::PoseRelation::kTranslation},
          {"rpe_rot", ev::PoseRelation::kRotationDeg}}) {
      Attempt(out, name, [&, name = std::string(name), relation = relation] {
        ev::RpeOptions options;
        options.pose_relation = relation;
        options.delta = evaluation.rpe_delta_m;
        options.delta_unit = ev::DeltaUnit::kMeters;
        options.association = association;
        AddStatistics(out, name, ev::Rpe(options).Compute(*inputs.reference, *inputs.estimate));
      });
    }
    if (!evaluation.rpe_segments_m || !evaluation.rpe_segments_m->empty()) {
      Attempt(out, "segment_rpe",
              [&] { AddSegmentRpe(out, evaluation, association, *inputs.reference, *inputs.estimate); });
    }
  }
  if (inputs.estimate && inputs.relations) {
    // Relations as the only reference: the coverage gate counts them (none covered until shown otherwise).
    if (!inputs.reference) out.relations_coverage = RelationsCoverage{0, inputs.relations->size()};
    Attempt(out, "relations", [&] {
      const ev::RelationsResult result =
          ev::RelationsMetric({}).Compute(*inputs.estimate, *inputs.relations, inputs.odometry);
      AddRelations(out.metrics, result, inputs.relations_outside_log);
      out.details["relations"] = result.ToJson();
      out.details["relations"]["outside_log"] = inputs.relations_outside_log;
      if (out.relations_coverage) out.relations_coverage->covered = result.used;
    });
    if (out.relations_coverage) {
      out.details["coverage"] = out.relations_coverage->ToJson();
      out.details["coverage"]["min_coverage"] = evaluation.min_coverage;
    }
  }
  if (inputs.reference && inputs.relations) {
    Attempt(out, "reference_floor", [&] {
      const ev::RelationsResult result =
          ev::RelationsMetric({}).Compute(*inputs.reference, *inputs.relations, inputs.odometry);
      AddRelations(out.reference_floor, result, inputs.relations_outside_log);
      out.reference_floor_details = result.ToJson();
      out.reference_floor_details["outside_log"] = inputs.relations_outside_log;
    });
  }
  if (inputs.map) {
    Attempt(out, "paper_map", [&] {
      ev::PaperMetricsOptions paper_options;
      paper_options.canvas.crop = evaluation.crop;
      // One scale for every program: the metrics count cells (blur, corner spacing, minimum areas),
      // so each map is scored on evaluation.map_resolution_m cells, grey levels kept.
      const ev::PaperMetrics paper = ev::ComputePaperMetrics(
          ev::ResampleKeepingProbabilities(*inputs.map, evaluation.map_resolution_m), paper_options);
      out.metrics.push_back({"occupied_to_free_unknown", "value", paper.occupied.occupied_to_free_unknown, "ratio"});
      out.metrics.push_back({"occupied_to_all", "value", paper.occupied.occupied_to_all, "ratio"});
      out.metrics.push_back({"unknown_to_all", "value", paper.occupied.unknown_to_all, "ratio"});
      out.metrics.push_back({"corners", "value", static_cast<double>(paper.corners.corners), "count"});
      out.metrics.push_back({"enclosed_areas", "value", static_cast<double>(paper.enclosed.enclosed_areas), "count"});
      out.details["paper_map"] = paper.ToJson();
      out.details["paper_map"]["resolution_m"] = evaluation.map_resolution_m;
      out.details["paper_map"]["map_resolution_m"] = inputs.map->resolution_m;
      if (inputs.map->resolution_m > evaluation.map_resolution_m * (1.0 + 1e-9)) {
        out.warnings.push_back(fmt::format(
            "paper_map: the map's {} m cells are scored on {} m cells (evaluation.map_resolution_m): each is repeated, "
            "so its staircase edges count as corners; score every map of the sweep at the coarsest cell size to "
            "compare maps of different cell sizes",
            inputs.map->resolution_m, evaluation.map_resolution_m));
      }
    });
  }
  if (inputs.map && inputs.reference_map) {
    Attempt(out, "map_compare", [&] {
      ev::MapCompareOptions options;
      if (ape_alignment) {
        const Eigen::Matrix3d& rotation = ape_alignment->rotation;
        options.transform = {ape_alignment->translation.x(), ape_alignment->translation.y(),
                             std::atan2(rotation(1, 0), rotation(0, 0))};
      } else {
        // No trajectory alignment (no reference trajectory, only a reference map file): search it.
        options.refine_with_icp = true;
      }
      const ev::OccupancyGrid& scored = inputs.written_map ? *inputs.written_map : *inputs.map;
      const ev::OccupancyGrid estimate = ev::ResampleToResolution(scored, inputs.reference_map->resolution_m, options);
      const ev::MapComparison compared = ev::CompareMaps(estimate, *inputs.reference_map, options);
      out.metrics.push_back({"map_chamfer", "value", compared.chamfer_m, "m"});
      out.metrics.push_back({"map_f1", "value", compared.f1, "ratio"});
      out.metrics.push_back({"map_accuracy", "value", compared.accuracy, "ratio"});
      out.metrics.push_back({"map_completeness", "value", compared.completeness, "ratio"});
      out.metrics.push_back({"map_iou_occupied", "value", compared.iou_occupied, "ratio"});
      out.metrics.push_back({"map_iou_free", "value", compared.iou_free, "ratio"});
      out.details["map_compare"] = compared.ToJson(options);
      out.details["map_compare"]["placement"] = ape_alignment ? "ATE alignment" : "ICP from identity";
      out.details["map_compare"]["scored_map"] = inputs.written_map ? "the run's map file" : "the program's map";
      if (estimate.resolution_m != scored.resolution_m) {
        out.details["map_compare"]["resampled_from_m"] = scored.resolution_m;
      }
      if (!inputs.reference_map_record.is_null())
        out.details["map_compare"]["reference_map"] = inputs.reference_map_record;
    });
  }
  return out;
}

}  // namespace slamsweep::orchestrator::inline worker
