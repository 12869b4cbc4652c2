#include "report/model/named_study.h"

#include <fstream>

#include "evaluator/core/input_error.h"
#include "orchestrator/store/named_study.h"

namespace slamsweep::report::inline model {

SweepModelOptions LoadSweepModelOptions(const std::filesystem::path& result_dir) {
  SweepModelOptions options;
  options.published = LoadDefaultPublishedFigures();
  const std::filesystem::path file = result_dir / orchestrator::kNamedStudyFile;
  if (!std::filesystem::exists(file)) return options;
  const orchestrator::NamedStudy named = orchestrator::ReadNamedStudy(file);
  options.named_study = named.study;
  options.named_study_source = named.source;
  return options;
}

}  // namespace slamsweep::report::inline model
