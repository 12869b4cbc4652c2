#include "orchestrator/worker/run_metrics.h"

#include <cmath>
#include <functional>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/map/paper_metrics.h"
#include "evaluator/map_compare/map_compare.h"
#include "evaluator/map_compare/map_resample.h"
#include "evaluator/trajectory/ape.h"
#include "evaluator/trajectory/relations_metric.h"
#include "evaluator/trajectory/rpe.h"

namespace slamsweep::orchestrator {

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

nlohmann::json ToJson(const FlatMetric& metric) {
  return {{"metric", metric.metric}, {"statistic", metric.statistic}, {"value", metric.value}, {"unit", metric.unit}};
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
    for (const auto& [name, relation] : {std::pair<const char*, ev::PoseRelation>{"ape_trans", ev::PoseRelation::kTranslation},
                                         {"ape_rot", ev::PoseRelation::kRotationDeg}}) {
      Attempt(out, name, [&, name = std::string(name), relation = relation] {
        const ev::Ape ape({relation, association, alignment});
        const ev::MetricResult result = ape.Compute(*inputs.reference, *inputs.estimate);
        if (relation == ev::PoseRelation::kTranslation) ape_alignment = result.alignment;
        AddStatistics(out, name, result);
      });
    }
    for (const auto& [name, relation] : {std::pair<const char*, ev::PoseRelation>{"rpe_trans", ev::PoseRelation::kTranslation},
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
  }
  if (inputs.estimate && inputs.relations) {
    Attempt(out, "relations", [&] {
      const ev::RelationsResult result = ev::RelationsMetric({}).Compute(*inputs.estimate, *inputs.relations);
      const double used = static_cast<double>(result.used);
      out.metrics.push_back({"relations_trans", "mean", result.translation_abs_mean_m, "m"});
      out.metrics.push_back({"relations_trans", "std", result.translation_abs_std_m, "m"});
      out.metrics.push_back({"relations_trans", "n", used, "count"});
      out.metrics.push_back({"relations_rot", "mean", result.rotation_abs_mean_deg, "deg"});
      out.metrics.push_back({"relations_rot", "std", result.rotation_abs_std_deg, "deg"});
      out.metrics.push_back({"relations_rot", "n", used, "count"});
      out.details["relations"] = result.ToJson();
    });
  }
  if (inputs.map) {
    Attempt(out, "paper_map", [&] {
      ev::PaperMetricsOptions paper_options;
      paper_options.canvas.crop = evaluation.crop;
      const ev::PaperMetrics paper = ev::ComputePaperMetrics(*inputs.map, paper_options);
      out.metrics.push_back({"occupied_to_free_unknown", "value", paper.occupied.occupied_to_free_unknown, "ratio"});
      out.metrics.push_back({"occupied_to_all", "value", paper.occupied.occupied_to_all, "ratio"});
      out.metrics.push_back({"unknown_to_all", "value", paper.occupied.unknown_to_all, "ratio"});
      out.metrics.push_back({"corners", "value", static_cast<double>(paper.corners.corners), "count"});
      out.metrics.push_back({"enclosed_areas", "value", static_cast<double>(paper.enclosed.enclosed_areas), "count"});
      out.details["paper_map"] = paper.ToJson();
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
      const ev::OccupancyGrid estimate = ev::ResampleToResolution(*inputs.map, inputs.reference_map->resolution_m, options);
      const ev::MapComparison compared = ev::CompareMaps(estimate, *inputs.reference_map, options);
      out.metrics.push_back({"map_chamfer", "value", compared.chamfer_m, "m"});
      out.metrics.push_back({"map_f1", "value", compared.f1, "ratio"});
      out.metrics.push_back({"map_accuracy", "value", compared.accuracy, "ratio"});
      out.metrics.push_back({"map_completeness", "value", compared.completeness, "ratio"});
      out.metrics.push_back({"map_iou_occupied", "value", compared.iou_occupied, "ratio"});
      out.metrics.push_back({"map_iou_free", "value", compared.iou_free, "ratio"});
      out.details["map_compare"] = compared.ToJson(options);
      out.details["map_compare"]["placement"] = ape_alignment ? "ATE alignment" : "ICP from identity";
      if (estimate.resolution_m != inputs.map->resolution_m) {
        out.details["map_compare"]["resampled_from_m"] = inputs.map->resolution_m;
      }
      if (!inputs.reference_map_record.is_null()) out.details["map_compare"]["reference_map"] = inputs.reference_map_record;
    });
  }
  return out;
}

}  // namespace slamsweep::orchestrator
