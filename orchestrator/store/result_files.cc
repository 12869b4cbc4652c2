#include "orchestrator/store/result_files.h"

#include "orchestrator/store/csv_tables.h"
#include "orchestrator/store/junit_xml.h"
#include "orchestrator/store/summary_json.h"
#include "orchestrator/store/validity_table.h"

namespace slamsweep::orchestrator {

void WriteResultFiles(const std::vector<StoredRun>& runs, const std::filesystem::path& output_dir) {
  const evaluator::ValidityStudy study = ValidityStudyOf(runs);
  WriteSummaryJson(runs, study, output_dir / "summary.json");
  WriteCsvTables(runs, study, output_dir);
  WriteJUnit(runs, output_dir / "junit.xml");
}

}  // namespace slamsweep::orchestrator
