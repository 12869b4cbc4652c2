#include "report/html/metric_spec_page.h"

#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "evaluator/validity/metric_validity.h"

namespace slamsweep::report::inline html {
namespace {

struct MetricDefinition {
  std::string name;
  std::string unit;
  std::string better;
  std::string definition;
};

struct Section {
  std::string title;
  std::string introduction;
  std::vector<MetricDefinition> metrics;
};

// The definitions follow spec/metrics.md (trajectory and paper map metrics) and
// evaluator/map_compare/README.md (map versus reference); the numbers are computed by the evaluator.
std::vector<Section> Sections() {
  const evaluator::ValidityOptions validity;
  return {
      {"Trajectory error against the reference",
       "Computed when the sequence has a reference trajectory. Each estimated pose is paired with the reference pose "
       "nearest in time (within t_max_diff, 0.01 s by default). Statistics over the pairs: rmse, mean, median, std "
       "(population), min, max, sse and n; tables show the RMSE over iterations as mean ± sample std.",
       {
           {"ape_trans", "m", "lower",
            "Absolute (trajectory) pose error, translation: |t_ref − t_est| per pair after aligning the estimate to "
            "the "
            "reference with the alignment named in the column (se2 by default: Umeyama's closed form without scale). "
            "Its RMSE is the paper's Table I (\"ATE\"). On a sequence whose reference is a corrected log (the "
            "Radish/Freiburg logs: GMapping's output), ATE and RPE measure agreement with the corrected log "
            "(GMapping's output), not error against independent truth: GMapping agrees with itself by construction, "
            "so there the relations error leads the tables and decides best."},
           {"ape_rot", "deg", "lower", "The same pairs, rotation: the angle of R_ref^T R_est."},
           {"rpe_trans", "m", "lower",
            "Relative pose error over consecutive pose pairs delta metres of travel apart (1 m by default): "
            "E = (P_ref_i^-1 P_ref_j)^-1 (P_est_i^-1 P_est_j), its translation part. No alignment is needed."},
           {"rpe_rot", "deg", "lower", "The rotation angle of the same E."},
           {"segment_trans_<L>m", "m", "lower",
            "Segment RPE (drift per segment length, as the KITTI odometry benchmark and rpg_trajectory_evaluation "
            "report "
            "it): for each length L, every reference pose is paired with the later pose whose path along the REFERENCE "
            "is nearest L (within 10 % of L), so every run of a sequence is scored on the same stretches whatever its "
            "own "
            "errors; per segment |t(E)| of the same E as rpe_trans, no alignment. At each L it equals evo's rpe with "
            "--delta L --delta_unit m --all_pairs --pairs_from_reference. The lengths (evaluation.rpe_segments_m) are "
            "10, 20, 30, 40 and 50 % of the sequence's whole reference path rounded to 1 m by default, the same for "
            "every "
            "run of a group, and part of the name (segment_trans_12m), so runs scored at other lengths never share a "
            "column. Statistics over the segments: mean, median, std, min, max, n; the run's segments are in "
            "rpe_segments.csv."},
           {"segment_drift_<L>m", "%", "lower",
            "The same segments: 100 |t(E)| / L, the translation drift in % of the "
            "segment length (the segment-length page's drift)."},
           {"segment_rot_<L>m", "deg/m", "lower", "The same segments: the rotation angle of E divided by L."},
           {"relations_trans", "m", "lower",
            "Kuemmerle et al. (2009): for every relation (t1, t2, expected motion) of the sequence's relations file, "
            "the "
            "estimated poses P1, P2 at t1 and t2 are taken and the error (P1^-1 P2) ⊖ expected; mean and std of "
            "the absolute translation error (relations outside the trajectory are skipped and counted: n used, "
            "skipped). Between two poses of the estimate, the pose at t is the last pose before t moved by the "
            "odometry the program was given from that pose's time to t (its recorded readings where denser than its "
            "scans), as a keyframe SLAM program itself places the robot between keyframes (GMapping's corrected logs "
            "are written this way); without odometry, linear interpolation (slerp for rotation). This deviates from "
            "plain interpolation because relation stamps name raw scans a keyframe estimate does not hold: linear "
            "interpolation across a turn on the spot adds error no program made. The reference floor row is the "
            "reference itself scored exactly the same way."},
           {"relations_rot", "deg", "lower", "The same relations, absolute rotation error: mean and std."},
       }},
      {"Map metrics without ground truth (the paper's profile)",
       "Filatov et al., \"2D SLAM Quality Evaluation Methods\" (2017), with this project's documented parameters. "
       "Every one is computed on the map cropped to its known cells plus a 2-cell margin, so unknown padding of the "
       "canvas changes nothing.",
       {
           {"occupied_to_free_unknown", "ratio", "lower",
            "Occupied proportion (section III.A): unknown cells count as p = 0; a cell is occupied when p is above the "
            "mean p of all cells; occupied / (free + unknown). Blurred or doubled walls raise it."},
           {"occupied_to_all", "ratio", "lower", "The same occupied cells over all cells."},
           {"unknown_to_all", "ratio", "—", "Unknown cells over all cells (a variant of the occupied proportion)."},
           {"corners", "count", "lower",
            "Corner count (section III.B): Laplacian of Gaussian (sigma 1 cell) of the map, structure above 10 % of "
            "its "
            "maximum with blobs under 5 cells dropped, Harris corners on it (block 2, aperture 3, k 0.04, response at "
            "least 1 % of the maximum, 10 cells apart). Artifacts add corners."},
           {"enclosed_areas", "count", "lower",
            "Enclosed areas (section III.C): unknown cells set to a grey level u, Otsu binarisation, free 8-connected "
            "regions of at least 4 cells not touching the border, counted by border following; the maximum over "
            "u = 0, 5, 10, ... 250. Superimposed rooms and failed loop closures add areas."},
       }},
      {"Map against the reference map",
       "Computed when the sequence has a reference. The reference map is the sequence's catalog map file, or the map "
       "rendered from the reference poses and the clean scans (before any range noise) with the odometry baseline's "
       "occupancy mapping at the evaluation cell size (0.05 m by default), cached per sequence. The run's map is "
       "brought to that cell size and placed on the reference by the ATE's se2 alignment (by ICP of occupied cells "
       "from "
       "identity when there is no trajectory alignment). Cells are occupied at p ≥ 0.65 and free at p ≤ 0.196 "
       "(map_saver's thresholds); unknown cells never count. Distances use an exact Euclidean distance transform "
       "between occupied cells.",
       {
           {"map_chamfer", "m", "lower",
            "Chamfer distance: the mean of the two directed mean distances, from each occupied map cell to the nearest "
            "occupied reference cell and from each occupied reference cell to the nearest occupied map cell. The run "
            "page's details also give each directed mean and maximum."},
           {"map_accuracy", "ratio", "higher",
            "Fraction of the map's occupied cells within r cells (2 by default) of an occupied reference cell: how "
            "many "
            "drawn walls are real (precision)."},
           {"map_completeness", "ratio", "higher",
            "Fraction of the reference's occupied cells within r cells of an occupied map cell: how many real walls "
            "are "
            "drawn (recall)."},
           {"map_f1", "ratio", "higher", "2 accuracy completeness / (accuracy + completeness)."},
           {"map_iou_occupied", "ratio", "higher",
            "Over the cells known (occupied or free) in both maps: cells occupied in both / cells occupied in either."},
           {"map_iou_free", "ratio", "higher", "The same for free cells."},
       }},
      {"Run resources",
       "Measured by the worker with wait4 for the SLAM program's process group; the odometry baseline runs no program "
       "(its wall time is the rendering of its map, and it has no peak memory).",
       {
           {"wall_s", "s", "lower", "Elapsed time of the program."},
           {"cpu_s", "s", "lower", "User plus system CPU time of the program and its children."},
           {"peak_rss_kb", "kB", "lower", "Peak resident memory of the program (shown in MiB on run pages)."},
       }},
      {"Statistics of the validity page (\"Which metrics can be trusted?\")",
       "Every ground-truth-free metric above (the three occupied proportions, corners, enclosed areas) and every run "
       "resource is set against each real error (ATE translation RMSE, relations translation mean, map Chamfer "
       "distance) over the successful runs whose odometry was not the reference.",
       {
           {"spearman_rho", "—", "closer to 1",
            "Spearman's rank correlation: the Pearson correlation of the ranks of the two quantities, tied values "
            "sharing the mean of their ranks. Runs are ranked only among runs of one stratum: one sequence with all "
            "its "
            "noise settings (\"all noise levels\"), or one sequence and one noise setting (\"within each noise "
            "level\", the runs one table compares). Over several strata each rank is centred on its stratum's mean "
            "rank and divided by the stratum's size before the correlation, so sequences of different scales are never "
            "ranked against each other. Every metric reads \"higher is worse\", so a metric that can be trusted has a "
            "rho near +1."},
           {"ci_low, ci_high", "—", "—",
            fmt::format(
                "{:g} % percentile bootstrap interval of rho: {} resamples of the runs drawn with replacement "
                "within each stratum, with a fixed seed ({}), so the same runs give the same interval everywhere.",
                100 * validity.bootstrap.confidence, validity.bootstrap.resamples, validity.bootstrap.seed)},
           {"verdict", "—", "—",
            fmt::format("\"tracks error\" when the whole interval is above 0, \"opposite\" when it is below 0, "
                        "\"unclear\" when it holds 0, \"no variation\" when a quantity is constant, \"too few runs\" "
                        "below {} runs (no number is given).",
                        validity.min_runs)},
       }},
  };
}

}  // namespace

std::string RenderMetricSpecPage(const SiteData& /*site*/) {
  const auto T = [](std::string_view markup) { return Html::Trusted(markup); };
  const auto E = [](std::string_view text) { return Html::Escape(text); };
  Html body = Element("p", "",
                      E("Every metric this report shows, by the name it has in result.json, summary.json "
                        "and the CSV files. Numbers computed under different specifications (alignment, "
                        "delta, thresholds) are never put in one table column; the column header states the "
                        "specification."));
  for (const Section& section : Sections()) {
    body += Element("h2", "", E(section.title));
    body += Element("p", "", E(section.introduction));
    Html rows;
    for (const MetricDefinition& metric : section.metrics) {
      rows += Element("tr", "",
                      Element("th", "", Element("code", "", E(metric.name))) + Element("td", "", E(metric.unit)) +
                          Element("td", "", E(metric.better)) + Element("td", "", E(metric.definition))) +
              T("\n");
    }
    Html header;
    for (const char* name : {"Metric", "Unit", "Better", "Definition"}) header += Element("th", "", E(name));
    body += T("<table class=\"definitions\">\n<thead>") + Element("tr", "", header) + T("</thead>\n<tbody>\n") + rows +
            T("</tbody>\n</table>\n");
  }
  return RenderPage("Metric specification", "", body);
}

}  // namespace slamsweep::report::inline html
