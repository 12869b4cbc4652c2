#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "orchestrator/store/results_store.h"

namespace slamsweep::orchestrator::inline store {

/// The thresholds of run.json ("thresholds": [{"metric", "statistic" (default "rmse"), "max", "min"}])
/// checked against a run's metrics.
struct ThresholdCheck {
  /// "ape_trans.rmse = 0.7 > 0.5", one per limit the run is past. A null value, a metric the run
  /// lacks and a malformed threshold are past it too: a limit that cannot be checked is not met.
  std::vector<std::string> exceeded;
};

ThresholdCheck CheckThresholds(const RunRecord& run);

/// Text made safe for XML 1.0 content and attribute values: & < > " ' escaped, tab/newline/CR kept (as
/// character references, so attributes keep them), other control characters and non-characters dropped,
/// invalid UTF-8 replaced by U+FFFD.
std::string XmlEscape(std::string_view text);

/// junit.xml: one <testsuite> per sequence, one <testcase classname="<sequence>.<noise>"
/// name="<algorithm> [<parameters>] i<iteration> (<run_id>)" time="<wall_s>"> per run (no brackets without
/// parameters); a failed run has <failure type="<failure_kind>" message="<reason>">, a run past a
/// threshold (or lacking a thresholded metric) <failure type="threshold">.
std::string RenderJUnit(const std::vector<RunRecord>& runs);

/// Writes RenderJUnit(runs) to `file` atomically.
void WriteJUnit(const std::vector<RunRecord>& runs, const std::filesystem::path& file);

}  // namespace slamsweep::orchestrator::inline store
