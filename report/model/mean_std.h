#pragma once

#include "evaluator/core/sample_summary.h"

namespace slamsweep::report::inline model {

// The report's cells use the evaluator's summary over iterations, as summary.json/csv do.
using evaluator::ComputeMeanStd;
using evaluator::MeanStd;

}  // namespace slamsweep::report::inline model
