// Plans the segment-length and parameter pages of report/html/view_pages.h: their models, paths and figures.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "report/html/artwork.h"
#include "report/html/number_format.h"
#include "report/html/view_pages.h"

namespace slamsweep::report::inline html {
namespace {

namespace fs = std::filesystem;

BoxplotFigure SegmentBoxplot(const SiteData& site, const SequenceModel& sequence, const SegmentTable& table,
                             std::optional<BoxSummary> SegmentCell::*box, const std::string& what,
                             const std::string& unit) {
  BoxplotFigure figure;
  // Short titles: gnuplot centres them over the picture; the page's caption names the sequence.
  figure.title = what + " of every segment, per segment length";
  figure.x_label = "segment length (chosen on the reference path)";
  figure.y_label = what + " (" + unit + ")";
  for (const double length : table.lengths_m) figure.categories.push_back(LengthLabel(length));
  for (const SegmentRow& row : table.rows) {
    BoxSeries series;
    series.label = sequence.rows[row.row].algorithm;
    series.style = RowStyle(site, sequence, row.row);
    for (const SegmentCell& cell : row.cells) series.boxes.push_back(cell.*box);
    figure.series.push_back(std::move(series));
  }
  return figure;
}

LineFigure DriftLines(const SiteData& site, const SequenceModel& sequence, const SegmentTable& table) {
  LineFigure figure;
  figure.title = "translation drift against segment length, mean ± std over runs";
  figure.x_label = "segment length (m)";
  figure.y_label = "translation drift (% of segment length)";
  for (const SegmentRow& row : table.rows) {
    LineSeries series;
    series.label = sequence.rows[row.row].algorithm;
    series.style = RowStyle(site, sequence, row.row);
    for (std::size_t k = 0; k < table.lengths_m.size(); ++k) {
      const MeanStd& drift = row.cells[k].mean_drift_pct;
      if (drift.n == 0) continue;
      series.points.push_back({table.lengths_m[k], drift.mean, drift.std, drift.n});
    }
    figure.series.push_back(std::move(series));
  }
  return figure;
}

std::string ColumnText(const MetricColumn& column) {
  return column.title + (column.unit.empty() ? "" : " (" + column.unit + ")");
}

LineFigure ParameterCurve(const SiteData& site, const SequenceModel& sequence, const ParameterSweep& sweep,
                          const ParameterSlice& slice, const ColumnRef& column) {
  const MetricColumn& metric = ColumnOf(sequence, column);
  const ParameterAxis& axis = sweep.axes[0];
  LineFigure figure;
  figure.title = sweep.algorithm + ": " + metric.title + (metric.spec.empty() ? "" : ", " + metric.spec);
  figure.x_label = axis.name;
  figure.y_label = ColumnText(metric) + ", mean ± std";
  LineSeries series;
  series.label = sweep.algorithm;
  const std::vector<std::size_t> rows = slice.Rows();
  if (!rows.empty()) series.style = RowStyle(site, sequence, rows.front());
  series.style.variant = 0;
  bool positive = axis.numeric;
  for (const nlohmann::json& value : axis.values) positive = positive && value.get<double>() > 0.0;
  const double smallest = axis.numeric ? axis.values.front().get<double>() : 0.0;
  const double largest = axis.numeric ? axis.values.back().get<double>() : 0.0;
  figure.log_x = positive && largest / smallest >= 20.0;
  if (!axis.numeric) {
    for (const nlohmann::json& value : axis.values) figure.x_tics.push_back(ParameterValueText(value));
  }
  const BestValue best = FindBest(sequence, rows, column);
  for (std::size_t x = 0; x < axis.values.size(); ++x) {
    const std::optional<std::size_t> row = slice.cells[0][x];
    if (!row) continue;
    const MeanStd& summary = CellOf(sequence.rows[*row], column).summary;
    if (summary.n == 0) continue;
    if (best.row && !best.tie && *best.row == *row) {
      figure.highlight = LineFigure::Highlight{0, series.points.size(),
                                               "lowest mean: " + axis.name + "=" + ParameterValueText(axis.values[x])};
    }
    series.points.push_back(
        {axis.numeric ? axis.values[x].get<double>() : static_cast<double>(x), summary.mean, summary.std, summary.n});
  }
  figure.series.push_back(std::move(series));
  return figure;
}

HeatmapFigure ParameterHeatmap(const SequenceModel& sequence, const ParameterSweep& sweep, const ParameterSlice& slice,
                               const ColumnRef& column) {
  const MetricColumn& metric = ColumnOf(sequence, column);
  HeatmapFigure figure;
  const std::string slice_text = SliceText(sweep, slice);
  figure.title = sweep.algorithm + ": " + metric.title + (metric.spec.empty() ? "" : ", " + metric.spec) +
                 (slice_text.empty() ? "" : " (" + slice_text + ")");
  figure.x_label = sweep.axes[0].name;
  figure.y_label = sweep.axes[1].name;
  figure.value_label = ColumnText(metric) + ", mean";
  for (const nlohmann::json& value : sweep.axes[0].values) figure.x_values.push_back(ParameterValueText(value));
  for (const nlohmann::json& value : sweep.axes[1].values) figure.y_values.push_back(ParameterValueText(value));
  const BestValue best = FindBest(sequence, slice.Rows(), column);
  for (const auto& line : slice.cells) {
    std::vector<HeatmapCell> cells;
    for (const std::optional<std::size_t>& row : line) {
      HeatmapCell cell;
      if (row) {
        const MeanStd& summary = CellOf(sequence.rows[*row], column).summary;
        if (summary.n > 0) {
          cell.value = summary.mean;
          cell.text = FormatMeanStd(summary);
        } else {
          cell.text = "no value";
        }
        cell.best = best.row && !best.tie && *best.row == *row;
      }
      cells.push_back(std::move(cell));
    }
    figure.cells.push_back(std::move(cells));
  }
  return figure;
}

}  // namespace

/// "sequences/<table>/": the folder of a table's extra pages and figures, beside its page
/// "sequences/<table>.html" (a folder and a .html file never share a name, and <table> is unique).
std::string TableFolder(const ReportLayout& layout, const std::string& table_key) {
  std::string page = layout.SequencePage(table_key);
  page.resize(page.size() - std::string_view(".html").size());
  return page + "/";
}

/// Adds a figure: its artefact (not made until drawn) and its job.
void AddFigure(TableViews& views, std::vector<FigureJob>& figures, const std::filesystem::path& out_dir,
               const std::string& id, const std::string& path, ViewFigure figure) {
  PlotArtifact artifact;
  artifact.metric = id;
  artifact.title = FigureTitle(figure);
  artifact.path = path;
  artifact.note = "no image maker configured";
  views.figures[id] = artifact;
  figures.push_back({std::move(figure), out_dir / path});
}

void Artwork::Figures(const std::vector<FigureJob>& figures) {
  if (!figures.empty())
    throw std::runtime_error("this image maker draws no figures of the segment-length and parameter pages");
}

std::string LengthLabel(double length_m) { return fmt::format("{} m", length_m); }

std::string SegmentFigureId(std::string_view what) { return "segments/" + std::string(what); }

std::string ParameterFigureId(std::size_t sweep, std::size_t slice, std::size_t column) {
  return fmt::format("parameters/{}/{}/{}", sweep, slice, column);
}

SeriesStyle RowStyle(const SiteData& site, const SequenceModel& sequence, std::size_t row) {
  const std::string& name = sequence.rows[row].name;
  SeriesStyle style;
  if (site.palette != nullptr) {
    const AlgorithmStyle algorithm = site.palette->StyleOf(name);
    style.rgb = algorithm.rgb;
    style.point_type = algorithm.point_type;
  }
  for (std::size_t r = 0; r < row; ++r) style.variant += sequence.rows[r].name == name ? 1 : 0;
  return style;
}

void PlanViewPages(const fs::path& out_dir, SiteData& site, std::vector<FigureJob>& figures) {
  const SweepModel& model = *site.model;
  for (const SequenceModel& sequence : model.sequences) {
    TableViews views;
    const std::string folder = TableFolder(*site.layout, sequence.key);
    views.segments = BuildSegmentTable(model, sequence);
    views.parameters = BuildParameterTable(model, sequence);
    if (!views.segments && !views.parameters) continue;
    std::error_code error;
    fs::create_directories(out_dir / folder, error);
    if (error)
      throw evaluator::InputError((out_dir / folder).string() + ": cannot create folder (" + error.message() + ")");

    if (views.segments) {
      views.segments_page = folder + "segments.html";
      const SegmentTable& table = *views.segments;
      AddFigure(views, figures, out_dir, SegmentFigureId("translation"), folder + "segments-translation.png",
                SegmentBoxplot(site, sequence, table, &SegmentCell::translation_m, "translation error", "m"));
      AddFigure(views, figures, out_dir, SegmentFigureId("rotation"), folder + "segments-rotation.png",
                SegmentBoxplot(site, sequence, table, &SegmentCell::rotation_deg_per_m, "rotation error", "deg/m"));
      AddFigure(views, figures, out_dir, SegmentFigureId("drift"), folder + "segments-drift.png",
                DriftLines(site, sequence, table));
    }
    if (views.parameters) {
      views.parameters_page = folder + "parameters.html";
      const std::vector<ColumnRef> columns = TableColumns(sequence);
      for (std::size_t s = 0; s < views.parameters->sweeps.size(); ++s) {
        const ParameterSweep& sweep = views.parameters->sweeps[s];
        for (std::size_t slice = 0; slice < sweep.slices.size(); ++slice) {
          for (std::size_t c = 0; c < columns.size(); ++c) {
            const std::string id = ParameterFigureId(s, slice, c);
            const std::string path = folder + fmt::format("parameters-{}-{}-{}.png", s, slice, c);
            if (sweep.axes.size() == 1) {
              AddFigure(views, figures, out_dir, id, path,
                        ParameterCurve(site, sequence, sweep, sweep.slices[slice], columns[c]));
            } else {
              AddFigure(views, figures, out_dir, id, path,
                        ParameterHeatmap(sequence, sweep, sweep.slices[slice], columns[c]));
            }
          }
        }
      }
    }
    site.views[sequence.key] = std::move(views);
  }
}

std::pair<std::size_t, std::size_t> MarkViewFigures(const fs::path& out_dir, bool drawing, const std::string& error,
                                                    SiteData& site) {
  std::size_t made = 0;
  std::size_t missing = 0;
  for (auto& [key, views] : site.views) {
    for (auto& [id, figure] : views.figures) {
      std::error_code ignored;
      figure.made = fs::is_regular_file(out_dir / figure.path, ignored);
      if (figure.made) {
        figure.note.clear();
        ++made;
      } else if (drawing) {
        figure.note = error.empty() ? "the figure file is missing" : error;
        ++missing;
      }
    }
  }
  return {made, missing};
}

std::size_t WriteViewPages(const SiteData& site, const fs::path& out_dir) {
  std::size_t pages = 0;
  const auto write = [&](const std::string& path, const std::string& content) {
    std::ofstream out(out_dir / path, std::ios::binary | std::ios::trunc);
    out << content;
    out.close();
    if (!out) throw evaluator::InputError((out_dir / path).string() + ": cannot write");
    ++pages;
  };
  for (const SequenceModel& sequence : site.model->sequences) {
    const auto views = site.views.find(sequence.key);
    if (views == site.views.end()) continue;
    if (!views->second.segments_page.empty()) {
      write(views->second.segments_page, RenderSegmentPage(site, sequence, views->second));
    }
    if (!views->second.parameters_page.empty()) {
      write(views->second.parameters_page, RenderParametersPage(site, sequence, views->second));
    }
  }
  return pages;
}

std::string ViewStyleSheet() {
  return PaletteStyleSheet() + R"(.swatch { font-size: 1.1em; }
ul.views { margin: 0.5em 0; }
img.figure { max-width: 100%; height: auto; }
figure.figure { max-width: 1400px; }
figure.figure-small { max-width: 560px; }
img.figure-small { max-width: 540px; width: 100%; height: auto; }
td.missing { color: #888; }
.legend-note { font-size: 0.9em; color: #333; }
)";
}

}  // namespace slamsweep::report::inline html
