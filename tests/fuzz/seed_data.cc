#include "tests/fuzz/seed_data.h"

#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "evaluator/simulation/simulated_sequence.h"
#include "tests/fuzz/fuzz_support.h"

namespace slamsweep::fuzz {
namespace {

const evaluator::SimulatedSequence& Simulation(int beams, double fov_rad) {
  static std::optional<evaluator::SimulatedSequence> simulated;
  static std::pair<int, double> made_for{0, 0.0};
  if (!simulated || made_for != std::pair{beams, fov_rad}) {
    evaluator::SimulationOptions options;
    options.floor_plan.rooms_per_side = 1;
    options.laser.beam_count = beams;
    options.laser.fov_rad = fov_rad;
    simulated = evaluator::SimulateSequence(options);
    made_for = {beams, fov_rad};
  }
  return *simulated;
}

}  // namespace

evaluator::RobotLog SeedLog(std::size_t scans, int beams, double fov_rad) {
  const evaluator::SimulatedSequence& simulated = Simulation(beams, fov_rad);
  evaluator::RobotLog log;
  log.name = "seed";
  for (std::size_t i = 0; i < scans && i < simulated.scans.size(); ++i) {
    log.scans.push_back(simulated.scans[i]);
    log.odometry.Add(simulated.odometry.stamps_s()[i], simulated.odometry.poses()[i]);
  }
  return log;
}

evaluator::Trajectory SeedGroundTruth(std::size_t scans) {
  const evaluator::SimulatedSequence& simulated = Simulation(181, std::numbers::pi);
  evaluator::Trajectory truth;
  for (std::size_t i = 0; i < scans && i < simulated.ground_truth.size(); ++i) {
    truth.Add(simulated.ground_truth.stamps_s()[i], simulated.ground_truth.poses()[i]);
  }
  return truth;
}

evaluator::OccupancyGrid SeedGrid() {
  evaluator::OccupancyGrid grid(40, 30, 0.05, {-1.0, -0.75, 0.0});
  for (int row = 2; row < 28; ++row) {
    for (int col = 2; col < 38; ++col) {
      const bool wall = row == 2 || row == 27 || col == 2 || col == 37 || (col == 20 && row < 18);
      grid.at(row, col) = wall ? 1.0f : 0.0f;
    }
  }
  grid.at(10, 10) = 0.5f;
  grid.at(11, 10) = 0.3f;
  return grid;
}

std::string FileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("seeds: cannot read " + path.string());
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void CheckSequenceRead(const std::filesystem::path& file, const std::function<evaluator::Sequence()>& read) {
  std::optional<evaluator::Sequence> sequence;
  ExpectReadOrInputError({file}, [&] { sequence = read(); });
  if (!sequence) return;
  try {
    evaluator::ValidateSequence(*sequence);
  } catch (const std::exception& error) {
    Require(false, std::string("a sequence read without error is invalid: ") + error.what());
  }
}

}  // namespace slamsweep::fuzz
