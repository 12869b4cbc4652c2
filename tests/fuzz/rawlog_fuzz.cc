// MRPT rawlogs through slamsweep's rawlog module (slamsweep-rawlog.so). The fuzz build calls the module in
// this process, where libFuzzer sees the coverage; the replay reads as slamsweep does (ReadSequence: the
// module in a child process under memory and time limits), so that the kept inputs that make MRPT ask for
// gigabytes are checked to be rejected there.
#include <numbers>
#include <string>

#include "evaluator/core/text_file.h"
#include "evaluator/sequence_io/format_modules.h"
#include "evaluator/sequence_io/robot_log_file.h"
#include "evaluator/sequence_io/sequence_file.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const ev::RobotLog log = fuzz::SeedLog(6, 181, std::numbers::pi);
  const std::filesystem::path written = seeds.folder() / "written.rawlog";
  for (const auto& [name, form] : {std::pair{"actions-sensory-frames", ev::RawlogForm::kActionsSensoryFrames},
                                   std::pair{"observations", ev::RawlogForm::kObservations}}) {
    ev::RawlogWriteOptions options;
    options.form = form;
    ev::RawlogSummary summary;
    ev::ThrowIfFailed(ev::LoadRawlogModule(written).write(log, written, options, summary));
    // MRPT reads plain and gzip rawlogs alike; plain bytes give the fuzzer the objects themselves.
    seeds.Add(std::string(name) + ".rawlog", ev::ReadTextFile(written));
    seeds.Add(std::string(name) + ".rawlog.gz", fuzz::FileBytes(written));
    std::filesystem::remove(written);
  }
  if (const auto head = seeds.SharedHead("datasets/intel/intel-mrpt-every5.rawlog.gz", 48 << 10, true, false)) {
    seeds.Add("intel-mrpt-every5-head.rawlog", *head);
  }
  // The inputs that once made slamsweep allocate gigabytes (../shared/fuzz/README.md).
  for (const std::filesystem::path& mutant : seeds.SharedFolder("fuzz/rawlog-mutants")) {
    if (mutant.extension() == ".rawlog") seeds.Add(mutant.filename().string(), fuzz::FileBytes(mutant));
  }
  // MRPT's own samples (Debian mrpt-common, which scripts/install-deps.sh installs).
  for (const char* sample :
       {"/usr/share/mrpt/datasets/localization_demo.rawlog", "/usr/share/mrpt/datasets/rot_scan_2d.rawlog"}) {
    if (std::filesystem::exists(sample)) {
      seeds.Add("mrpt-" + std::filesystem::path(sample).filename().string(), fuzz::FileBytes(sample));
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.rawlog", fuzz::Bytes(data, size));
#if defined(SLAMSWEEP_FUZZING)
  fuzz::CheckSequenceRead(file, [&] {
    ev::Sequence sequence;
    ev::ThrowIfFailed(ev::LoadRawlogModule(file).read(file, ev::RawlogReadOptions{}, sequence));
    return sequence;
  });
#else
  fuzz::CheckSequenceRead(file, [&] { return ev::ReadSequence(file); });
#endif
  return 0;
}
