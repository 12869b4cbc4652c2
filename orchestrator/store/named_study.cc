#include "orchestrator/store/named_study.h"

#include <fstream>

#include "evaluator/core/input_error.h"
#include "orchestrator/files/atomic_file.h"

namespace slamsweep::orchestrator::inline store {

NamedStudy ReadNamedStudy(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw evaluator::InputError(file.string() + ": cannot read the validity study");
  nlohmann::json whole;
  try {
    whole = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw evaluator::InputError(file.string() + ": not JSON (" + error.what() + ")");
  }
  if (!whole.is_object() || !whole.contains("validity") || !whole.at("validity").is_object()) {
    throw evaluator::InputError(file.string() +
                                ": no \"validity\" object (expected a summary.json of a sweep with reference data)");
  }
  NamedStudy named;
  named.source = whole.contains("source") && whole.at("source").is_string() ? whole.at("source").get<std::string>()
                                                                            : file.string();
  named.json = whole.at("validity");
  try {
    named.study = evaluator::ValidityStudyFromJson(named.json);
  } catch (const evaluator::InputError& error) {
    throw evaluator::InputError(file.string() + ": " + error.what());
  }
  if (named.study.empty()) throw evaluator::InputError(file.string() + ": the study covers no sequence");
  return named;
}

void WriteNamedStudy(const NamedStudy& study, const std::filesystem::path& output_dir) {
  const nlohmann::json out = {{"source", study.source}, {"validity", study.json}};
  WriteFileAtomically(output_dir / kNamedStudyFile, out.dump(1) + "\n");
}

}  // namespace slamsweep::orchestrator::inline store
