// `slamsweep history record|compare`: nightly sweeps accumulate in a history database and are compared
// (Mann-Whitney U + Cliff's delta) to find regressions; exit 3 when there is one.
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/sweep_loading.h"
#include "evaluator/core/input_error.h"
#include "orchestrator/history/history_store.h"
#include "orchestrator/history/regression.h"
#include "orchestrator/files/atomic_file.h"

namespace slamsweep::cli {
namespace {

namespace history = slamsweep::orchestrator;

struct RecordOptions {
  std::string result_dir;
  std::string history_file;
  std::string label;
};

struct CompareOptions {
  std::string result_dir;
  std::string history_file;
  std::string baseline_label;
  bool previous = false;
  history::RegressionOptions regression;
  /// A sweep config whose `regression:` block gives alpha and min_effect (the options win when given).
  std::string config;
  bool alpha_given = false;
  bool min_effect_given = false;
  bool json = false;
  std::string junit;
};

void Record(const RecordOptions& options, const Streams& streams) {
  const history::Night night = history::ReadNight(options.result_dir, options.label);
  history::HistoryStore store = history::HistoryStore::Open(options.history_file);
  const auto outcome = store.Record(night);
  if (outcome.inserted) {
    streams.out << fmt::format("recorded night '{}' ({} series, {} cells) from {} in {}\n", night.label,
                               night.series.size(), night.cells.size(), night.result_dir.string(),
                               options.history_file);
  } else {
    const auto existing = store.FindByKey(night.result_dir, night.sweep_id);
    streams.out << fmt::format("already recorded as night '{}': {} (sweep {}) — nothing to do\n",
                               existing ? existing->label : night.label, night.result_dir.string(), night.sweep_id);
  }
}

// The night the current sweep is compared with: a named one, or the last one recorded before it.
history::Night Baseline(const history::HistoryStore& store, const history::Night& current,
                        const CompareOptions& options) {
  if (!options.baseline_label.empty()) {
    const auto found = store.FindByLabel(options.baseline_label);
    if (!found) {
      throw evaluator::InputError(
          fmt::format("--baseline-label: no night '{}' in {}; `slamsweep history record` "
                      "it first, or use --previous",
                      options.baseline_label, options.history_file));
    }
    return store.Load(found->id);
  }
  const auto previous = history::PreviousNight(store, current);
  if (!previous) {
    throw evaluator::InputError(fmt::format("--previous: {} holds no night before {}; record a baseline first",
                                            options.history_file, current.result_dir.string()));
  }
  return store.Load(previous->id);
}

void PrintTable(const history::Comparison& comparison, std::ostream& out) {
  out << fmt::format("{} -> {} (alpha {}, min |delta| {})\n", comparison.baseline_label, comparison.current_label,
                     comparison.options.alpha, comparison.options.min_effect);
  out << fmt::format("{:<15} {:<48} {:>12} {:>12} {:>5} {:>10} {:>7}\n", "verdict", "series", "baseline", "current",
                     "n", "p", "delta");
  for (const history::Finding& f : comparison.findings) {
    out << fmt::format(
        "{:<15} {:<48} {:>12.6g} {:>12.6g} {:>2}/{:<2} {:>10.4g} {:>+7.3f}\n", history::VerdictName(f.verdict),
        fmt::format("{}/{}/{}/{} {}.{}", f.algorithm, f.sequence, f.noise, f.odometry, f.metric, f.statistic),
        f.baseline_median, f.current_median, f.baseline_n, f.current_n, f.test.p_value, f.cliffs_delta);
  }
  out << fmt::format("{} regressions, {} improvements, {} unchanged, {} not comparable\n",
                     comparison.Count(history::Verdict::kRegression), comparison.Count(history::Verdict::kImprovement),
                     comparison.Count(history::Verdict::kUnchanged),
                     comparison.Count(history::Verdict::kNotComparable));
}

int Compare(CompareOptions options, const Streams& streams) {
  if (options.previous == !options.baseline_label.empty()) {
    throw evaluator::InputError("history compare: expected exactly one of --baseline-label NAME or --previous");
  }
  history::ValidateRegressionOptions(options.regression, "--");
  if (!options.config.empty()) {
    const orchestrator::RegressionConfig configured = LoadSweep(options.config, {}).config.regression;
    if (!options.alpha_given) options.regression.alpha = configured.alpha;
    if (!options.min_effect_given) options.regression.min_effect = configured.min_effect;
  }
  const history::Night current = history::ReadNight(options.result_dir, "");
  const history::HistoryStore store = history::HistoryStore::OpenExisting(options.history_file);
  const history::Night baseline = Baseline(store, current, options);
  const history::Comparison comparison = history::CompareNights(baseline, current, options.regression);
  if (!options.junit.empty()) {
    orchestrator::WriteFileAtomically(options.junit, history::RenderComparisonJUnit(comparison));
  }
  if (options.json) {
    streams.out << history::ComparisonToJson(comparison).dump(2) << "\n";
  } else {
    PrintTable(comparison, streams.out);
  }
  return comparison.HasRegression() ? history::kRegressionExitCode : 0;
}

}  // namespace

void RegisterHistoryCommands(CLI::App& app, const Streams& streams, int& exit_code) {
  CLI::App* command = app.add_subcommand("history", "nightly history: record sweeps, compare them for regressions");
  command->require_subcommand(1);

  auto record = std::make_shared<RecordOptions>();
  CLI::App* record_command = command->add_subcommand("record", "append a sweep's results as one night");
  record_command->add_option("RESULT_DIR", record->result_dir, "the sweep's output directory")->required();
  record_command->add_option("--history", record->history_file, "history database (created when missing)")->required();
  record_command->add_option("--label", record->label, "name of the night (default: the sweep's start time)");
  record_command->callback([record, &streams] { Record(*record, streams); });

  auto compare = std::make_shared<CompareOptions>();
  CLI::App* compare_command =
      command->add_subcommand("compare", "compare a sweep with an earlier night; exit 3 on a regression");
  compare_command->add_option("RESULT_DIR", compare->result_dir, "the sweep's output directory")->required();
  compare_command->add_option("--history", compare->history_file, "history database")->required();
  auto* label = compare_command->add_option("--baseline-label", compare->baseline_label, "the night to compare with");
  auto* previous =
      compare_command->add_flag("--previous", compare->previous, "compare with the night recorded before this one");
  label->excludes(previous);
  auto* alpha =
      compare_command->add_option("--alpha", compare->regression.alpha, "significance level of the Mann-Whitney U test")
          ->capture_default_str();
  auto* min_effect =
      compare_command->add_option("--min-effect", compare->regression.min_effect, "minimum |Cliff's delta|")
          ->capture_default_str();
  compare_command->add_option("--config", compare->config,
                              "sweep YAML whose regression: {alpha, min_effect} to use (the options above win)");
  compare_command->add_flag("--json", compare->json, "print the comparison as JSON");
  compare_command->add_option("--junit", compare->junit, "write a JUnit file: one failing testcase per regression");
  compare_command->callback([compare, alpha, min_effect, &streams, &exit_code] {
    compare->alpha_given = alpha->count() > 0;
    compare->min_effect_given = min_effect->count() > 0;
    exit_code = Compare(*compare, streams);
  });
}

}  // namespace slamsweep::cli
