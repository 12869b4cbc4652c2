#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "evaluator/statistics/friedman.h"
#include "evaluator/statistics/sign_test.h"
#include "report/model/significance.h"
#include "report/model/sweep_model.h"

namespace slamsweep::report::inline model {

/// One table of a setting and whether it counts as a data set of the verdict across data sets.
struct DataSetChoice {
  std::string table_key;  ///< SequenceModel::key
  std::string table_title;
  std::string metric;  ///< the headline it is ranked by, with its unit ("relations translation error (m)")
  bool used = false;
  /// Why it counts ("relations (Kuemmerle et al.): independent of every program") or why not ("ATE against a
  /// corrected log: GMapping's output, agreement rather than error", "the same physical run as X, ...").
  std::string why;
};

/// A contestant of the verdict: one ranked row (algorithm x parameters x build) present in every data set.
struct DataSetContestant {
  std::string label;  ///< AlgorithmRow::algorithm
  double mean_rank = 0.0;
  /// The row's mean of the headline metric per data set used (DataSetVerdict::used order), and its rank there.
  std::vector<double> values;
  std::vector<double> ranks;
};

/// Demšar's comparison of the contestants over the data sets of one noise setting and odometry mode: mean ranks,
/// Friedman with Iman-Davenport, and Nemenyi's critical difference.
struct DataSetVerdict {
  std::string noise;
  std::string odometry;                   ///< "recorded", "reference", "" (not recorded)
  std::vector<DataSetChoice> data_sets;   ///< every table of the setting, used or not
  std::vector<std::string> used;          ///< the titles of the data sets used, in table order
  std::vector<std::string> used_metrics;  ///< their headline metrics (DataSetChoice::metric)
  /// Sorted by mean rank (best first).
  std::vector<DataSetContestant> contestants;
  /// Rows ranked on some data set but left out, with why ("tinyslam: not ranked on fr079 (4 of 5 runs ok)").
  std::vector<std::string> left_out;
  /// At least two data sets and three contestants: the Friedman test and Nemenyi's CD were computed.
  bool tested = false;
  evaluator::FriedmanResult friedman;
  double alpha = 0.05;
  double critical_difference = 0.0;  ///< Nemenyi's CD at alpha
  /// Pairs (indices into contestants, better first) whose mean ranks differ by at least the CD; empty unless
  /// the Friedman test (Iman-Davenport) rejects at alpha.
  std::vector<std::pair<std::size_t, std::size_t>> different;
  /// The fewest data sets at which the CD would fall to the largest possible difference (k - 1: some pair could
  /// differ), and to the largest difference observed here; 0 when not needed or beyond reach.
  std::size_t data_sets_for_any_difference = 0;
  std::size_t data_sets_for_observed_difference = 0;
  /// Two contestants: the sign test over the data sets (the lower mean rank's wins) instead of Friedman's.
  std::optional<evaluator::SignTestResult> sign_test;
  /// The conclusion in a sentence or two.
  std::string verdict;
};

/// One verdict per noise setting and odometry mode of the sweep's tables that has at least two data sets. A data
/// set is a table whose headline metric (`significance`) measures error against an independent reference: the
/// relations, or ATE against exact ground truth; ATE against a corrected log is agreement with GMapping and does
/// not count. Tables scored on one relations file are one physical run and count once: the one whose runs got
/// the most scans per second. Contestants are the rows ranked in every data set used (never the odometry
/// baseline, reference, published or flagged rows).
std::vector<DataSetVerdict> BuildAcrossDataSets(const SweepModel& model,
                                                const std::vector<TableSignificance>& significance,
                                                double alpha = 0.05);

}  // namespace slamsweep::report::inline model
