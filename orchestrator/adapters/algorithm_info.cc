#include "orchestrator/adapters/algorithm_info.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "evaluator/core/input_error.h"
#include "orchestrator/adapters/mrpt_settings.h"
#include "orchestrator/adapters/roster.h"
#include "orchestrator/config/program_path.h"
#include "orchestrator/process/process_set.h"

namespace slamsweep::orchestrator::inline adapters {

namespace fs = std::filesystem;

namespace {

constexpr const char* kIcpSlamDefaultsNote =
    "chosen on intel's first 300 scans, a sequence sweeps also score (points-map ICP, a scan inserted every "
    "0.5 m / 20 deg, the ICP thresholds of MRPT's points-map demo, widening rays); re-checked on the simulated "
    "floor (exact truth, 5 % odometry noise, 5 draws): ATE 0.023 m against the template's 0.061 m, better in "
    "5 of 5 draws; on intel's first 200 scans 0.13 m against 10.7 m (bench/defaults/recheck.yaml)";
constexpr const char* kCartographerDefaultsNote =
    "slamsweep_2d.lua's correlative scan matching, 0.1 deg motion filter and optimisation every 30 nodes were "
    "chosen for intel's scan spacing, a sequence sweeps also score; re-checked on the simulated floor (exact "
    "truth, 5 % odometry noise, 3 draws): ATE 0.079 m (0.074-0.086) against upstream's values' 0.084 m "
    "(0.044-0.121), so kept; on intel's first 200 scans 0.64 m against 3.13 m, the odometry's 3.16 m "
    "(bench/defaults/recheck.yaml)";

constexpr const char* kSlamToolboxDefaultsNote =
    "upstream's own: every parameter as config/mapper_params_offline.yaml, the offline node's file, sets it "
    "(Karto's built-in defaults differ in 15 of them and none is used); Ceres and TBB run on one thread so that "
    "a run repeats";
constexpr const char* kLamaDefaultsNote =
    "iris_lama_ros's offline launch file (launch/slam2d_offine.launch): d_thresh 0.5, a_thresh 0.5, mrange 20 "
    "where the slam2d_ros node's own defaults are 0.01, 0.25 and 16; the node's defaults otherwise";
constexpr const char* kLamaPfDefaultsNote =
    "iris_lama_ros's offline launch file (launch/pf_slam2d_offine.launch): particles 30, d_thresh 0.5, a_thresh "
    "0.5, mrange 20 where the pf_slam2d_ros node's own a_thresh is 0.25 and mrange 16; the node's defaults "
    "otherwise, but threads 1 (the launch file's 4 share one random generator: not repeatable) and the seed, the "
    "run's folded to 32 bits with 0 replaced by 2654435769 (LaMa takes 0 for a fresh random seed)";

/// stdout+stderr of a short probe (a driver's --list-parameters, dpkg-query), or nullopt when it fails.
std::optional<std::string> ProbeOutput(std::vector<std::string> argv) {
  const fs::path log = fs::temp_directory_path() / ("slamsweep-probe-" + std::to_string(::getpid()) + ".txt");
  ProcessSpec spec;
  spec.argv = std::move(argv);
  spec.log_path = log;
  spec.timeout_s = 30;
  const ProcessOutcome outcome = RunProcess(spec);
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  std::error_code ignored;
  fs::remove(log, ignored);
  if (!outcome.ok()) return std::nullopt;
  return text.str();
}

std::vector<std::pair<std::string, std::string>> KeyValueLines(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> pairs;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t equals = line.find('=');
    if (equals != std::string::npos && equals > 0) pairs.emplace_back(line.substr(0, equals), line.substr(equals + 1));
  }
  return pairs;
}

AlgorithmInfo DescribeRoster(const RosterAlgorithm& algorithm) {
  AlgorithmInfo info{std::string(algorithm.name),
                     std::string(algorithm.title),
                     false,
                     "",
                     std::string(algorithm.license),
                     std::string(SeedingName(algorithm.seeding)),
                     {},
                     "upstream names; unknown names fail the run",
                     ""};
  std::optional<nlohmann::json> manifest;
  try {
    manifest = ReadRosterManifest(algorithm);
  } catch (const evaluator::InputError& error) {
    info.status = error.what();
    return info;
  }
  if (!manifest) {
    info.status = "not installed: scripts/install-slam.sh " + std::string(algorithm.upstream) +
                  " && scripts/build.sh, or `slamsweep plan`/`run` of a sweep that uses it builds it first (from a "
                  "build tree)";
    return info;
  }
  const std::string commit = manifest->value("commit", "");
  info.status = std::string(algorithm.upstream) + " " + commit.substr(0, 12) + " (tarball sha256 " +
                manifest->value("tarball_sha256", "").substr(0, 16) + ")";
  fs::path driver;
  try {
    driver = RosterDriver(algorithm);
  } catch (const evaluator::InputError& error) {
    info.status += "; driver not built: scripts/build.sh (or `slamsweep plan`/`run` of a sweep that uses it)";
    return info;
  }
  info.installed = true;
  if (const auto listed = ProbeOutput({driver.string(), "--list-parameters"})) info.parameters = KeyValueLines(*listed);
  return info;
}

AlgorithmInfo DescribeMrpt(const std::string& adapter, const std::string& program, const std::string& title,
                           Seeding seeding, const std::vector<IniSetting>& defaults, const std::string& template_path) {
  AlgorithmInfo info{adapter,
                     title,
                     false,
                     "",
                     "BSD-3-Clause",
                     std::string(SeedingName(seeding)),
                     {},
                     "any Section.key of " + template_path,
                     ""};
  try {
    ResolveProgram(program, fs::current_path());
    info.installed = true;
    const auto version = ProbeOutput({"dpkg-query", "-W", "-f", "${Version}", "mrpt-apps"});
    info.status = "mrpt-apps " + (version ? *version : std::string("(version unknown)"));
  } catch (const evaluator::InputError&) {
    info.status = "not installed: apt install mrpt-apps (scripts/install-deps.sh)";
  }
  for (const IniSetting& setting : defaults)
    info.parameters.emplace_back(setting.section + "." + setting.key, setting.value);
  return info;
}

/// Where slamsweep's own defaults were tuned and how they fared on a sequence they were not tuned on
/// (bench/defaults/recheck.yaml: the simulated floor, exact truth, 5 % odometry noise); for the algorithms beyond
/// the paper, which upstream file the defaults come from and where the driver departs from it.
std::string DefaultsNote(const std::string& adapter) {
  if (adapter == "mrpt-icp-slam") return kIcpSlamDefaultsNote;
  if (adapter == "cartographer") return kCartographerDefaultsNote;
  if (adapter == "slam-toolbox") return kSlamToolboxDefaultsNote;
  if (adapter == "lama") return kLamaDefaultsNote;
  if (adapter == "lama-pf") return kLamaPfDefaultsNote;
  return "";
}

}  // namespace

std::vector<AlgorithmInfo> DescribeAlgorithms() {
  std::vector<AlgorithmInfo> all;
  for (const RosterAlgorithm& algorithm : Roster()) all.push_back(DescribeRoster(algorithm));
  all.push_back(DescribeMrpt("mrpt-icp-slam", "icp-slam", "MRPT icp-slam", Seeding::kDeterministic,
                             IcpSlamDefaultSettings(), kIcpSlamTemplate));
  all.push_back(DescribeMrpt("mrpt-rbpf-slam", "rbpf-slam", "MRPT rbpf-slam", Seeding::kSeeded,
                             {{"MappingApplication", "sampleSize", "5"}}, kRbpfSlamTemplate));
  all.push_back(AlgorithmInfo{"odometry",
                              "odometry baseline (the odometry as the trajectory)",
                              true,
                              "built in",
                              "-",
                              std::string(SeedingName(Seeding::kDeterministic)),
                              {},
                              "none",
                              ""});
  all.push_back(AlgorithmInfo{"command",
                              "any SLAM program through a declared command",
                              true,
                              "built in",
                              "the program's",
                              "seeded when its argv uses {seed} or {seed32}",
                              {},
                              "{param:NAME} in its argv",
                              ""});
  for (AlgorithmInfo& info : all) info.defaults_note = DefaultsNote(info.adapter);
  return all;
}

}  // namespace slamsweep::orchestrator::inline adapters
