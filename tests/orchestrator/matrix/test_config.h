#pragma once

// Small sweeps built in code (not from YAML), so matrix tests do not depend on the config reader.
#include <string>
#include <vector>

#include "orchestrator/config/sweep_config.h"

namespace slamsweep::orchestrator::testing {

inline SequenceSpec Sequence(const std::string& name) {
  SequenceSpec sequence;
  sequence.entry.name = name;
  sequence.entry.format = "carmen";
  sequence.entry.path = "/data/" + name + ".log";
  return sequence;
}

inline NoiseSpec Noise(const std::string& name, double alpha1) {
  NoiseSpec noise;
  noise.name = name;
  if (alpha1 > 0.0) noise.odometry = evaluator::OdometryNoise{alpha1, 0.0, 0.0, 0.0, 0.0, 0.0};
  return noise;
}

inline AlgorithmConfig Algorithm(const std::string& name, const std::string& adapter,
                                 std::vector<ParameterAxis> parameters = {}) {
  AlgorithmConfig algorithm;
  algorithm.name = name;
  algorithm.adapter = adapter;
  algorithm.parameters = std::move(parameters);
  return algorithm;
}

/// icp (p: [1, 2], q: ["a", "b"]) and odo x seq1, seq2 x clean, noisy x 2 iterations = (4 + 1) * 2 * 2 * 2 = 40.
inline SweepConfig TwoByTwo() {
  SweepConfig config;
  config.name = "t";
  config.iterations = 2;
  config.seed = 42;
  config.algorithms = {Algorithm("icp", "mrpt-icp-slam", {{"p", {1, 2}}, {"q", {"a", "b"}}}),
                       Algorithm("odo", "odometry")};
  config.sequences = {Sequence("seq1"), Sequence("seq2")};
  config.noise = {Noise("clean", 0.0), Noise("noisy", 0.01)};
  return config;
}

}  // namespace slamsweep::orchestrator::testing
