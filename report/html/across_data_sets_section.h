#pragma once

#include <vector>

#include "report/html/html.h"
#include "report/model/across_data_sets.h"

namespace slamsweep::report::inline html {

/// The overview's opening section: per noise setting and odometry mode with at least two data sets, the verdict
/// across data sets (mean ranks, Friedman with Iman-Davenport, Nemenyi's critical difference as a diagram), which
/// tables counted and why, and which rows were left out. Empty when no setting has two data sets.
Html AcrossDataSetsSection(const std::vector<DataSetVerdict>& verdicts);

/// The critical-difference diagram (Demšar 2006) as inline SVG, attributes only (no script, no style): the mean
/// rank axis (1 = best at the left), each contestant at its mean rank, the critical difference as a bar, and a
/// thick line joining each run of contestants that no test tells apart.
Html CriticalDifferenceDiagram(const DataSetVerdict& verdict);

}  // namespace slamsweep::report::inline html
