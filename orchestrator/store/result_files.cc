#include "orchestrator/store/result_files.h"

#include <optional>

#include "orchestrator/phase_times/phase_times.h"
#include "orchestrator/store/csv_tables.h"
#include "orchestrator/store/junit_xml.h"
#include "orchestrator/store/summary_json.h"
#include "orchestrator/store/validity_table.h"

namespace slamsweep::orchestrator::inline store {

void WriteResultFiles(const std::vector<RunRecord>& runs, const std::filesystem::path& output_dir) {
  std::optional<PhaseTimer> phase(std::in_place, "validity");
  const DigestedValidityStudy study = ValidityStudyOf(runs);
  phase.emplace("summary_json");
  WriteSummaryJson(runs, study, output_dir / "summary.json");
  phase.emplace("csv");
  WriteCsvTables(runs, study.study, output_dir);
  phase.emplace("junit");
  WriteJUnit(runs, output_dir / "junit.xml");
}

}  // namespace slamsweep::orchestrator::inline store
