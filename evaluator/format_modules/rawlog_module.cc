// slamsweep-rawlog.so: the MRPT rawlog reader and writer as a module that slamsweep loads only
// when it reads or writes a rawlog (evaluator/format_modules/format_module.h says why).
#include "evaluator/formats/rawlog/rawlog_reader.h"
#include "evaluator/formats/rawlog/rawlog_writer.h"
#include "evaluator/format_modules/format_module.h"

namespace slamsweep::evaluator::inline format_modules {
namespace {

ModuleOutcome Read(const std::filesystem::path& path, const RawlogReadOptions& options, Sequence& sequence) {
  return RunGuarded([&] { sequence = ReadRawlog(path, options); });
}

ModuleOutcome Write(const RobotLog& log, const std::filesystem::path& path, const RawlogWriteOptions& options,
                    RawlogSummary& summary) {
  return RunGuarded([&] { summary = WriteRawlog(log, path, options); });
}

}  // namespace
}  // namespace slamsweep::evaluator::inline format_modules

extern "C" __attribute__((visibility("default"))) const slamsweep::evaluator::RawlogModule* slamsweep_rawlog_module() {
  static const slamsweep::evaluator::RawlogModule module{.read = &slamsweep::evaluator::Read,
                                                         .write = &slamsweep::evaluator::Write};
  return &module;
}
