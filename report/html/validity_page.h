#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "evaluator/validity/metric_validity.h"
#include "report/html/artwork.h"
#include "report/html/site_data.h"
#include "report/html/write_report.h"

namespace slamsweep::report::inline html {

/// One scatter plot of the validity page: a candidate metric (x) against a real error (y) on one sequence.
struct ValidityPlot {
  std::string candidate;
  std::string target;
  std::string sequence;
  std::string title;
  std::string path;  ///< relative to the report root
  bool made = false;
  std::string note;  ///< why it is missing
};

/// What validity.html shows: the study (evaluator/validity, computed from the runs exactly as the
/// store computes summary.json's "validity") and its plots.
struct ValiditySite {
  evaluator::ValidityStudy study;
  std::vector<ValidityPlot> plots;
  bool has_csv = false;  ///< validity.csv was copied from the sweep
};

/// The study of the sweep's runs, and one scatter plot per target present x candidate x sequence
/// with at least two runs: a series per noise setting and algorithm. With several noise settings the
/// colour grades them light to dark in the natural order of their names (GradedColour) and the marker
/// is the algorithm's (`palette`); with one, colour and marker are the algorithm's. The key says which.
/// Plots go to plots/validity/. An empty study (no reference data) plans nothing.
ValiditySite PlanValidity(const SweepModel& model, const AlgorithmPalette& palette,
                          const std::filesystem::path& out_dir, std::vector<ScatterPlotJob>& jobs);

/// Marks the plots whose files exist and counts them into `summary` (missing ones only when drawing).
void CountValidityPlots(const std::filesystem::path& out_dir, bool drawing, ValiditySite& validity,
                        ReportSummary& summary);

/// validity.html, "Which metrics can be trusted?": per real error, a table of every candidate's
/// Spearman rho with its bootstrap interval, run count and verdict for every sequence and for all
/// sequences, ranked across noise settings and within each; then the scatter plots.
std::string RenderValidityPage(const SiteData& site, const ValiditySite& validity);

}  // namespace slamsweep::report::inline html
