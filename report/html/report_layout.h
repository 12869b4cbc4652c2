#pragma once

#include <map>
#include <string>
#include <vector>

#include "report/model/sweep_model.h"

namespace slamsweep::report::inline html {

/// Where everything goes inside the report folder. Every name is made with SafeFileName and
/// made unique, so hostile run ids, algorithm or sequence names can neither escape the folder
/// nor overwrite each other's files. All paths are relative to the report root, with '/'.
class ReportLayout {
 public:
  explicit ReportLayout(const SweepModel& model);

  /// "runs/<name>.html"
  std::string RunPage(std::size_t run) const { return "runs/" + run_names_[run] + ".html"; }
  /// "runs/<name>/": the run's images and downloadable files.
  std::string RunDir(std::size_t run) const { return "runs/" + run_names_[run] + "/"; }
  /// "sequences/<sequence>-<noise>.html" of a table, by its SequenceModel::key.
  std::string SequencePage(const std::string& table_key) const;
  /// "plots/<sequence>-<noise>-<metric>.png"
  std::string Plot(const std::string& table_key, const std::string& metric) const;
  /// "files/<row>/<sequence>-<noise>/": the paper service's text files of one row (AlgorithmRow::algorithm,
  /// the algorithm with its varying parameters) in one table.
  std::string FilesDir(const std::string& row_label, const std::string& table_key) const;

 private:
  std::vector<std::string> run_names_;
  std::map<std::string, std::string> sequence_names_;
  std::map<std::string, std::string> algorithm_names_;
};

}  // namespace slamsweep::report::inline html
