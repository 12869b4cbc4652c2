#include "orchestrator/slurm/array_job.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "orchestrator/sweep/worker_environment.h"

namespace slamsweep::orchestrator::inline slurm {

std::int64_t TimeLimitMinutes(double timeout_s, double overhead_s) {
  const double total_s = std::max(0.0, timeout_s) + std::max(0.0, overhead_s);
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(total_s / 60.0)));
}

std::uint64_t TaskMemoryMb(std::uint64_t memory_limit_mb, std::uint64_t overhead_mb) {
  return memory_limit_mb == 0 ? 0 : memory_limit_mb + overhead_mb;
}

std::vector<std::string> SbatchArgv(const ArrayJobRequest& request) {
  std::string array = "--array=0-";
  array += std::to_string(request.task_count == 0 ? 0 : request.task_count - 1);
  if (request.max_parallel > 0) {
    array += '%';
    array += std::to_string(request.max_parallel);
  }
  std::vector<std::string> argv = {"sbatch", "--parsable", array, "--job-name=" + request.job_name,
                                   "--time=" + std::to_string(request.time_limit_min),
                                   "--output=" + request.slurm_output_pattern.string(),
                                   // The run folders are absolute; the working directory only has to exist.
                                   "--chdir=" + request.script_path.parent_path().string()};
  if (request.memory_mb > 0) argv.push_back("--mem=" + std::to_string(request.memory_mb) + "M");
  if (!request.partition.empty()) argv.push_back("--partition=" + request.partition);
  argv.insert(argv.end(), request.extra_args.begin(), request.extra_args.end());
  argv.push_back(request.script_path.string());
  return argv;
}

std::string ShellQuote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  quoted += '\'';
  return quoted;
}

std::string BatchScript(const std::filesystem::path& worker_program, const std::filesystem::path& manifest) {
  std::ostringstream script;
  script << "#!/bin/sh\n"
         << "# Written by slamsweep's Slurm executor: array task N runs the run folder on line N+1 of the\n"
         << "# manifest, exactly as the local executor would (`slamsweep worker RUN_DIR`).\n"
         << "manifest=" << ShellQuote(manifest.string()) << "\n"
         << "run_dir=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" \"$manifest\")\n"
         << "if [ -z \"$run_dir\" ] || [ ! -d \"$run_dir\" ]; then\n"
         << "  echo \"slamsweep: no run folder for array task $SLURM_ARRAY_TASK_ID in $manifest\" >&2\n"
         << "  exit 2\n"
         << "fi\n";
  for (const auto& [name, value] : WorkerEnvironment()) {
    // Computed where sbatch runs (the orchestrator's environment, which sbatch exports).
    script << name << "=" << ShellQuote(value) << "\nexport " << name << "\n";
  }
  script << "exec " << ShellQuote(worker_program.string()) << " worker \"$run_dir\" >\"$run_dir/worker.log\" 2>&1\n";
  return script.str();
}

std::int64_t ParseSbatchJobId(const std::string& output) {
  // sbatch may print warnings first; the id is the last line.
  std::istringstream lines(output);
  std::string line;
  std::int64_t id = -1;
  while (std::getline(lines, line)) {
    const std::string head = line.substr(0, line.find(';'));
    if (head.empty() || head.size() > 18) continue;
    bool digits = true;
    for (const char c : head) digits = digits && std::isdigit(static_cast<unsigned char>(c)) != 0;
    if (digits) id = std::stoll(head);
  }
  return id;
}

}  // namespace slamsweep::orchestrator::inline slurm
