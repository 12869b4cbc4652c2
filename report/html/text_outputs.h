#pragma once

#include <string>

#include "report/model/sweep_model.h"

namespace slamsweep::report::inline html {

/// The paper service's text files for one algorithm on one sequence, as "name: value" lines.
/// rmse.txt: ATE translation RMSE mean and std (with its alignment); corners.txt and
/// occupied_ratio.txt: mean and std over iterations. std reads "n/a" for one iteration.
std::string RmseText(const SequenceModel& sequence, const AlgorithmRow& row);
std::string MapMetricText(const SequenceModel& sequence, const AlgorithmRow& row, const std::string& metric);

}  // namespace slamsweep::report::inline html
