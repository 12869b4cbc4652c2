// Kuemmerle et al. relations files (t1 t2 x y z roll pitch yaw per line).
#include "evaluator/formats/trajectory/relations_format.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/seed_data.h"

namespace ev = slamsweep::evaluator;
namespace fuzz = slamsweep::fuzz;

SLAMSWEEP_FUZZ_SEEDS(seeds) {
  const ev::Trajectory truth = fuzz::SeedGroundTruth(40);
  ev::Relations relations;
  for (std::size_t i = 0; i + 5 < truth.size(); i += 3) {
    const ev::Pose& from = truth.poses()[i];
    const ev::Pose& to = truth.poses()[i + 5];
    relations.push_back({truth.stamps_s()[i], truth.stamps_s()[i + 5],
                         ev::Pose::FromIsometry(from.ToIsometry().inverse() * to.ToIsometry())});
  }
  const std::filesystem::path written = seeds.folder() / "simulated.relations";
  ev::WriteRelations(relations, written);
  seeds.Add("simulated.relations", fuzz::FileBytes(written));
  for (const char* shared : {"datasets/intel/intel.relations", "datasets/fr079/fr079.relations",
                             "datasets/mit-killian/mit-killian.relations"}) {
    if (const auto head = seeds.SharedHead(shared, 6 << 10)) {
      seeds.Add(std::filesystem::path(shared).filename().string(), *head);
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = fuzz::WriteInput("input.relations", fuzz::Bytes(data, size));
  fuzz::ExpectReadOrInputError({file}, [&] { ev::ReadRelations(file); });
  return 0;
}
