#include "orchestrator/slurm/slurm_states.h"

#include <charconv>
#include <map>

#include "orchestrator/process/signal_name.h"

namespace slamsweep::orchestrator::inline slurm {
namespace {

std::optional<int> ToInt(std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::vector<std::string_view> Split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

/// "3:0" -> exit 3, "0:11" -> signal 11 (Slurm's "exit code:signal").
void ReadExitCode(std::string_view text, SlurmTaskState& task) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) return;
  const auto code = ToInt(text.substr(0, colon));
  const auto signal = ToInt(text.substr(colon + 1));
  if (code) task.exit_code = *code;
  if (signal) task.signal = *signal;
}

/// "CANCELLED by 0" -> "CANCELLED", "COMPLETING+" stays comparable.
std::string BareState(std::string_view text) {
  const std::size_t end = text.find_first_of(" +");
  return std::string(text.substr(0, end));
}

void AddTasks(const std::set<int>& ids, const SlurmTaskState& like, std::vector<SlurmTaskState>& out) {
  for (const int id : ids) {
    SlurmTaskState task = like;
    task.task_id = id;
    out.push_back(task);
  }
}

}  // namespace

std::set<int> ParseArrayTaskIds(std::string_view text) {
  std::set<int> ids;
  text = text.substr(0, text.find('%'));  // the throttle is not a task
  if (!text.empty() && text.front() == '[' && text.back() == ']') text = text.substr(1, text.size() - 2);
  if (text.empty()) return ids;
  for (const std::string_view part : Split(text, ',')) {
    const std::size_t dash = part.find('-');
    if (dash == std::string_view::npos) {
      const auto id = ToInt(part);
      if (!id) return {};
      ids.insert(*id);
      continue;
    }
    const auto first = ToInt(part.substr(0, dash));
    const auto last = ToInt(part.substr(dash + 1));
    if (!first || !last || *first > *last || *last - *first > 1000000) return {};
    for (int id = *first; id <= *last; ++id) ids.insert(id);
  }
  return ids;
}

std::vector<SlurmTaskState> ParseScontrolJobs(std::string_view text) {
  std::vector<SlurmTaskState> tasks;
  for (std::string_view line : Split(text, '\n')) {
    std::map<std::string_view, std::string_view> fields;
    for (const std::string_view word : Split(line, ' ')) {
      const std::size_t equals = word.find('=');
      if (equals != std::string_view::npos) fields.emplace(word.substr(0, equals), word.substr(equals + 1));
    }
    const auto ids = fields.find("ArrayTaskId");
    const auto state = fields.find("JobState");
    if (ids == fields.end() || state == fields.end()) continue;
    SlurmTaskState task;
    task.state = BareState(state->second);
    if (const auto exit = fields.find("ExitCode"); exit != fields.end()) ReadExitCode(exit->second, task);
    AddTasks(ParseArrayTaskIds(ids->second), task, tasks);
  }
  return tasks;
}

std::vector<SlurmTaskState> ParseSacct(std::string_view text) {
  std::vector<SlurmTaskState> tasks;
  for (const std::string_view line : Split(text, '\n')) {
    const std::vector<std::string_view> columns = Split(line, '|');
    if (columns.size() < 3) continue;
    const std::string_view job_id = columns[0];
    const std::size_t underscore = job_id.find('_');
    // Steps (".batch", ".extern") repeat their task; the task's own line is the one to read.
    if (underscore == std::string_view::npos || job_id.find('.') != std::string_view::npos) continue;
    SlurmTaskState task;
    task.state = BareState(columns[1]);
    ReadExitCode(columns[2], task);
    AddTasks(ParseArrayTaskIds(job_id.substr(underscore + 1)), task, tasks);
  }
  return tasks;
}

bool IsFinalState(std::string_view state) {
  static const std::set<std::string_view> kFinal = {"COMPLETED", "FAILED",       "TIMEOUT",   "OUT_OF_MEMORY",
                                                    "CANCELLED", "NODE_FAIL",    "PREEMPTED", "BOOT_FAIL",
                                                    "DEADLINE",  "SPECIAL_EXIT", "REVOKED"};
  return kFinal.count(state) > 0;
}

SlurmTaskEnding EndingForState(const SlurmTaskState& task, bool cancelled_by_us) {
  const std::string& state = task.state;
  if (state == "TIMEOUT") return {"Slurm TIMEOUT (--time limit)", false};
  if (state == "OUT_OF_MEMORY") return {"Slurm OUT_OF_MEMORY (--mem limit)", false};
  if (state == "NODE_FAIL") return {"Slurm NODE_FAIL (the node running the task failed)", false};
  if (state == "CANCELLED") {
    if (cancelled_by_us) return {"Slurm CANCELLED (the sweep was interrupted)", true};
    return {"Slurm CANCELLED (scancel by a user or an administrator)", false};
  }
  if (state == "PREEMPTED") return {"Slurm PREEMPTED (a higher-priority job took the node)", false};
  if (state == "BOOT_FAIL") return {"Slurm BOOT_FAIL (the node could not boot)", false};
  if (state == "DEADLINE") return {"Slurm DEADLINE (the job's --deadline passed)", false};
  std::string detail;
  if (task.signal != 0) {
    detail =
        "worker killed by " + std::string(SignalName(task.signal)) + " (signal " + std::to_string(task.signal) + ")";
  } else if (task.exit_code >= 0) {
    detail = "worker exit code " + std::to_string(task.exit_code);
  } else {
    detail = "worker exit status unknown";
  }
  return {"Slurm " + (state.empty() ? std::string("UNKNOWN") : state) + ": " + detail, false};
}

}  // namespace slamsweep::orchestrator::inline slurm
