#include "report/html/report_layout.h"

#include <cctype>
#include <set>

#include "report/html/safe_name.h"

namespace slamsweep::report::inline html {

namespace {

// SafeFileName already separates names that differ; this guards the remaining case of two
// names that are equal after folding case (a case-insensitive file system would merge them).
std::string Unique(std::string name, std::set<std::string>& taken) {
  auto folded = [](std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  };
  std::string candidate = name;
  for (int i = 2; taken.count(folded(candidate)) > 0; ++i) candidate = name + "-" + std::to_string(i);
  taken.insert(folded(candidate));
  return candidate;
}

}  // namespace

ReportLayout::ReportLayout(const SweepModel& model) {
  std::set<std::string> taken_runs;
  for (const RunRecord& run : model.runs) run_names_.push_back(Unique(SafeFileName(run.run_id), taken_runs));
  // One page per table (sequence x noise); its file name is the sequence's, plus the noise.
  std::set<std::string> taken_sequences;
  for (const SequenceModel& sequence : model.sequences) {
    sequence_names_[sequence.key] = Unique(SafeFileName(sequence.name + "-" + sequence.noise), taken_sequences);
  }
  // One folder of text files per row label (algorithm with its varying parameters).
  std::set<std::string> taken_algorithms;
  for (const SequenceModel& sequence : model.sequences) {
    for (const AlgorithmRow& row : sequence.rows) {
      if (algorithm_names_.count(row.algorithm) == 0) {
        algorithm_names_[row.algorithm] = Unique(SafeFileName(row.algorithm), taken_algorithms);
      }
    }
  }
}

std::string ReportLayout::SequencePage(const std::string& sequence) const {
  return "sequences/" + sequence_names_.at(sequence) + ".html";
}

std::string ReportLayout::Plot(const std::string& sequence, const std::string& metric) const {
  return "plots/" + sequence_names_.at(sequence) + "-" + SafeFileName(metric) + ".png";
}

std::string ReportLayout::FilesDir(const std::string& algorithm, const std::string& sequence) const {
  return "files/" + algorithm_names_.at(algorithm) + "/" + sequence_names_.at(sequence) + "/";
}

}  // namespace slamsweep::report::inline html
