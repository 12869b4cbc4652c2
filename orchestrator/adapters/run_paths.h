#pragma once

#include <filesystem>

namespace slamsweep::orchestrator::inline adapters {

/// The fixed layout of one run folder (orchestrator/DESIGN.md, "Output directory"). Adapters and
/// the worker name files only through it, so the layout is written down once.
struct RunPaths {
  std::filesystem::path root;

  std::filesystem::path RunJson() const { return root / "run.json"; }
  std::filesystem::path CommandTxt() const { return root / "command.txt"; }
  std::filesystem::path Log() const { return root / "log.txt"; }
  /// What the program reads (rawlog, ini, CARMEN log...).
  std::filesystem::path InputDir() const { return root / "input"; }
  /// The program's own output folder ({output_dir} of a command).
  std::filesystem::path RawDir() const { return root / "raw"; }
  /// Where the program runs: its output folder. Its input is in ../input; the run's truth
  /// (reference.tum) and result are written into the run folder only after it has exited.
  std::filesystem::path ProgramWorkingDir() const { return RawDir(); }
  /// Stage maps as separate images (run folders written before the stage animation).
  std::filesystem::path StagesDir() const { return root / "stages"; }
  /// Every stage map, in build order, as one animated PNG.
  std::filesystem::path StageAnimation() const { return root / "stages.png"; }
  std::filesystem::path MapYaml() const { return root / "map.yaml"; }
  std::filesystem::path TrajectoryTum() const { return root / "trajectory.tum"; }
  std::filesystem::path ReferenceTum() const { return root / "reference.tum"; }
  std::filesystem::path GeoJson() const { return root / "map.geojson"; }
  /// Every segment of the segment RPE (evaluator/formats/trajectory/segment_errors_csv.h).
  std::filesystem::path SegmentErrorsCsv() const { return root / "rpe_segments.csv"; }
  std::filesystem::path ResultJson() const { return root / "result.json"; }
};

}  // namespace slamsweep::orchestrator::inline adapters
