#include "report/html/trajectory_figures.h"

#include "report/html/view_pages.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/trajectory/tum_format.h"
#include "evaluator/trajectory_metrics/alignment.h"
#include "evaluator/trajectory_metrics/association.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;

using html_shorthand::E;

/// A gnuplot datablock of 100k points is slow to draw and no sharper at 900 px: every k-th pose.
constexpr std::size_t kMaxPathPoints = 4000;

std::size_t Stride(std::size_t size) { return std::max<std::size_t>(1, (size + kMaxPathPoints - 1) / kMaxPathPoints); }

struct AlignedRun {
  evaluator::Trajectory reference;
  evaluator::Trajectory estimate;         ///< whole trajectory, aligned onto the reference
  evaluator::Trajectory paired_estimate;  ///< associated poses, aligned
  evaluator::Trajectory paired_reference;
};

// The run's trajectory aligned onto its reference as its ATE was computed (the run's evaluation settings).
std::optional<AlignedRun> Align(const RunRecord& run) {
  if (run.status != RunStatus::kOk || run.outputs.trajectory.empty() || run.outputs.reference.empty())
    return std::nullopt;
  const OverlaySettings settings = OverlaySettingsOf(run);
  AlignedRun aligned;
  aligned.reference = evaluator::ReadTum(run.dir / run.outputs.reference);
  aligned.estimate = evaluator::ReadTum(run.dir / run.outputs.trajectory);
  const evaluator::Association pairs =
      evaluator::Associate(aligned.reference, aligned.estimate, {.t_max_diff_s = settings.t_max_diff_s});
  aligned.paired_reference = pairs.reference;
  aligned.paired_estimate = pairs.estimate;
  const evaluator::AlignmentMode mode = evaluator::ParseAlignmentMode(settings.align);
  if (mode != evaluator::AlignmentMode::kNone) {
    if (const auto alignment = evaluator::ComputeAlignment(pairs.reference, pairs.estimate, {.mode = mode})) {
      aligned.estimate = evaluator::ApplyAlignment(aligned.estimate, *alignment);
      aligned.paired_estimate = evaluator::ApplyAlignment(aligned.paired_estimate, *alignment);
    }
  }
  return aligned;
}

PathSeries SeriesOf(const evaluator::Trajectory& trajectory, std::string label, SeriesStyle style) {
  PathSeries series;
  series.label = std::move(label);
  series.style = style;
  const std::size_t stride = Stride(trajectory.size());
  for (std::size_t i = 0; i < trajectory.size(); i += stride) {
    series.x.push_back(trajectory.poses()[i].position.x());
    series.y.push_back(trajectory.poses()[i].position.y());
  }
  return series;
}

// The run coloured by its translation error at every associated pose, over the associated reference poses.
PathFigure ErrorFigure(const AlignedRun& aligned, const std::string& row_label, const std::string& run_id,
                       SeriesStyle style) {
  PathFigure error;
  error.title = row_label + " (" + run_id + "): translation error along the path";
  error.colour_label = "translation error (m)";
  PathSeries reference = SeriesOf(aligned.paired_reference, "reference", {});
  reference.reference = true;
  error.series.push_back(std::move(reference));
  PathSeries path = SeriesOf(aligned.paired_estimate, row_label, style);
  const std::size_t stride = Stride(aligned.paired_estimate.size());
  for (std::size_t i = 0; i < aligned.paired_estimate.size(); i += stride) {
    path.colour_values.push_back(
        (aligned.paired_estimate.poses()[i].position - aligned.paired_reference.poses()[i].position).head<2>().norm());
  }
  error.series.push_back(std::move(path));
  return error;
}

}  // namespace

OverlaySettings OverlaySettingsOf(const RunRecord& run) {
  OverlaySettings settings;
  const auto evaluation = run.run_spec.find("evaluation");
  if (evaluation == run.run_spec.end() || !evaluation->is_object()) return settings;
  if (const auto align = evaluation->find("align"); align != evaluation->end() && align->is_string()) {
    settings.align = align->get<std::string>();
  }
  if (const auto t = evaluation->find("t_max_diff_s"); t != evaluation->end() && t->is_number()) {
    settings.t_max_diff_s = t->get<double>();
  }
  return settings;
}

std::string PathErrorFigureId(std::size_t row) { return fmt::format("trajectories/error/{}", row); }

void PlanTrajectoryFigures(const fs::path& out_dir, SiteData& site, std::vector<FigureJob>& figures) {
  const SweepModel& model = *site.model;
  for (const SequenceModel& sequence : model.sequences) {
    if (!sequence.has_reference) continue;
    PathFigure together;
    together.title = "Median run of each row, aligned onto the reference";
    std::vector<std::pair<std::size_t, PathFigure>> errors;
    bool have_reference = false;
    for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
      const AlgorithmRow& row = sequence.rows[r];
      if (!row.median_run) continue;
      const RunRecord& run = model.runs[*row.median_run];
      std::optional<AlignedRun> aligned;
      try {
        aligned = Align(run);
      } catch (const evaluator::InputError&) {
        continue;  // unreadable or unalignable: the run page's overlay says why
      }
      if (!aligned || aligned->paired_estimate.empty()) continue;
      if (!have_reference) {
        PathSeries reference = SeriesOf(aligned->reference, "reference", {});
        reference.reference = true;
        together.series.insert(together.series.begin(), std::move(reference));
        have_reference = true;
      }
      const SeriesStyle style = RowStyle(site, sequence, r);
      together.series.push_back(SeriesOf(aligned->estimate, row.algorithm, style));

      PathFigure error = ErrorFigure(*aligned, row.algorithm, run.run_id, style);
      errors.emplace_back(r, std::move(error));
    }
    if (!have_reference) continue;
    const std::string folder = TableFolder(*site.layout, sequence.key);
    std::error_code error_code;
    fs::create_directories(out_dir / folder, error_code);
    if (error_code) {
      throw evaluator::InputError((out_dir / folder).string() + ": cannot create folder (" + error_code.message() +
                                  ")");
    }
    TableViews& views = site.views[sequence.key];
    AddFigure(views, figures, out_dir, kTrajectoriesFigureId, folder + "trajectories.png", std::move(together));
    for (auto& [row, figure] : errors) {
      AddFigure(views, figures, out_dir, PathErrorFigureId(row), folder + fmt::format("path-error-{}.png", row),
                std::move(figure));
    }
  }
}

void PlanRunPathErrorFigures(const fs::path& out_dir, SiteData& site, std::vector<FigureJob>& figures, bool every_run) {
  const SweepModel& model = *site.model;
  for (const SequenceModel& sequence : model.sequences) {
    if (!sequence.has_reference) continue;
    const auto views = site.views.find(sequence.key);
    for (std::size_t r = 0; r < sequence.rows.size(); ++r) {
      const AlgorithmRow& row = sequence.rows[r];
      for (const std::size_t index : row.runs) {
        RunArtifacts& artifacts = site.runs[index];
        if (row.median_run == index) {
          if (views == site.views.end()) continue;
          const auto figure = views->second.figures.find(PathErrorFigureId(r));
          if (figure != views->second.figures.end()) artifacts.path_error = figure->second.path;
          continue;
        }
        if (!every_run) continue;
        const RunRecord& run = model.runs[index];
        std::optional<AlignedRun> aligned;
        try {
          aligned = Align(run);
        } catch (const evaluator::InputError& error) {
          artifacts.notes.push_back(std::string("Translation error along the path not made: ") + error.what());
          continue;
        }
        if (!aligned || aligned->paired_estimate.empty()) continue;
        artifacts.path_error = site.layout->RunDir(index) + "path-error.png";
        figures.push_back({ErrorFigure(*aligned, row.algorithm, run.run_id, RowStyle(site, sequence, r)),
                           out_dir / artifacts.path_error});
      }
    }
  }
}

std::pair<std::size_t, std::size_t> MarkRunPathErrorFigures(const fs::path& out_dir, bool drawing,
                                                            const std::string& error, SiteData& site) {
  std::size_t made = 0, missing = 0;
  for (std::size_t i = 0; i < site.runs.size(); ++i) {
    RunArtifacts& artifacts = site.runs[i];
    if (artifacts.path_error.empty()) continue;
    std::error_code error_code;
    artifacts.path_error_made = fs::is_regular_file(out_dir / artifacts.path_error, error_code);
    // A median run's figure is its table's, counted with the table's figures.
    const bool own = artifacts.path_error.starts_with(site.layout->RunDir(i));
    if (!own) continue;
    if (artifacts.path_error_made) {
      ++made;
    } else if (drawing) {
      ++missing;
      artifacts.notes.push_back("Translation error along the path not made: " +
                                (error.empty() ? std::string("the figure file is missing") : error));
    }
  }
  return {made, missing};
}

Html TrajectoriesSection(const SiteData& site, const SequenceModel& sequence, std::string_view root) {
  const auto views = site.views.find(sequence.key);
  if (views == site.views.end()) return {};
  const auto figure = [&](const std::string& id, const char* css) -> Html {
    const auto found = views->second.figures.find(id);
    if (found == views->second.figures.end()) return {};
    const PlotArtifact& artifact = found->second;
    if (!artifact.made) return Element("p", "note", E(artifact.title + ": not drawn (" + artifact.note + ")"));
    return Element("figure", css,
                   ImageElement(std::string(root) + artifact.path, artifact.title, css) +
                       Element("figcaption", "", E(artifact.title)));
  };
  Html together = figure(kTrajectoriesFigureId, "figure");
  if (together.str().empty()) return {};
  Html body = Element("h2", "", E("Trajectories"));
  body +=
      Element("p", "note",
              E("Each row's median run by ATE, aligned onto the reference as its ATE was computed (the run's "
                "alignment and time tolerance), at one scale. Below, each of those runs coloured by its translation "
                "error at every associated pose."));
  body += together;
  Html errors;
  for (std::size_t r = 0; r < sequence.rows.size(); ++r) errors += figure(PathErrorFigureId(r), "figure-small");
  body += Element("div", "gallery", errors);
  return body;
}

}  // namespace slamsweep::report::inline html
