// The reference map of a run: rendered from the clean scans at the reference poses, cached per
// sequence (safe under concurrent workers, keyed by what the map depends on), or read from the
// catalog's file. The rendered map is checked against the simulated floor plan the scans were cast
// in (an independent map of the truth); the cache is checked against the evaluator's mapper.
#include "orchestrator/reference_map/reference_map.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include "evaluator/core/input_error.h"
#include "evaluator/formats/map/map_server_format.h"
#include "evaluator/occupancy_mapping/occupancy_mapper.h"
#include "evaluator/catalog/catalog.h"
#include "evaluator/simulation/floor_plan.h"
#include "evaluator/simulation/simulated_sequence.h"
#include "orchestrator/adapters/run_inputs.h"
#include "tests/orchestrator/worker/run_spec_fixture.h"
#include "tests/support/shared_data.h"

namespace slamsweep::orchestrator {
namespace {

namespace ev = slamsweep::evaluator;
namespace fs = std::filesystem;

/// -1 unknown, 0 free, 1 occupied: the classes map comparison sees (p >= 0.65 occupied, p <= 0.196 free).
std::vector<int> Classes(const ev::OccupancyGrid& grid) {
  std::vector<int> classes;
  for (float p : grid.cells)
    classes.push_back(ev::OccupancyGrid::IsUnknown(p) ? -1 : p >= 0.65f ? 1 : p <= 0.196f ? 0 : -1);
  return classes;
}

/// The map of the first `scans` clean scans of the simulated floor at its exact poses, straight
/// from the evaluator's mapper with its default options.
ev::OccupancyGrid ExpectedMap(std::size_t scans, double resolution_m) {
  ev::Sequence sequence = ev::LoadCatalogSequence(testing::SimulatedRun("odometry").sequence.entry, {});
  sequence.scans.resize(scans);
  ev::OccupancyMapperOptions options;
  options.resolution_m = resolution_m;
  return ev::OccupancyMapper(options).Build(sequence.scans, *sequence.reference).grid;
}

class ReferenceMapTest : public ::testing::Test {
 protected:
  void SetUp() override { spec_ = testing::SimulatedRun("odometry", 60); }
  fs::path Cache() const { return dir_ / "reference_maps"; }

  slamsweep::testing::TempDir dir_;
  RunSpec spec_;
};

TEST_F(ReferenceMapTest, TheCacheLivesBesideTheRunsFolder) {
  EXPECT_EQ(ReferenceMapCacheDir("/out/runs/r1"), fs::path("/out/reference_maps"));
  EXPECT_EQ(ReferenceMapCacheDir("/out/runs/r1/"), fs::path("/out/reference_maps"));
}

TEST_F(ReferenceMapTest, TheKeyHoldsWhatTheMapDependsOnAndNothingElse) {
  const std::string name = ReferenceMapCacheName(spec_);
  EXPECT_TRUE(name.starts_with("simulated-floor-")) << name;
  // Another algorithm, noise, seed or iteration: the same reference.
  RunSpec other = spec_;
  other.algorithm.name = other.algorithm.adapter = "mrpt-icp-slam";
  other.noise.name = "noisy";
  other.noise.range = ev::RangeNoise{};
  other.noise.range->sigma_m = 0.05;
  other.seed = 99;
  other.iteration = 4;
  EXPECT_EQ(ReferenceMapCacheName(other), name);
  // Another cell size, cut or sequence: another map.
  RunSpec coarse = spec_;
  coarse.evaluation.map_resolution_m = 0.1;
  RunSpec shorter = spec_;
  shorter.sequence.max_scans = 30;
  RunSpec floor2 = spec_;
  floor2.sequence.entry.simulation["floor_plan"]["seed"] = 2;
  for (const RunSpec* changed : {&coarse, &shorter, &floor2}) EXPECT_NE(ReferenceMapCacheName(*changed), name);
  const nlohmann::json key = ReferenceMapKey(spec_);
  EXPECT_EQ(key["mapper_revision"], ev::kOccupancyMapperRevision);
  EXPECT_EQ(key["resolution_m"], 0.05);
  EXPECT_FALSE(key["sequence"].contains("citation"));
}

/// Whether a wall of `plan` lies within `cells` cells of the world point (x, y).
bool NearWall(const ev::OccupancyGrid& plan, double x_m, double y_m, int cells) {
  const int col = static_cast<int>(std::floor((x_m - plan.origin.x_m) / plan.resolution_m));
  const int row_from_bottom = static_cast<int>(std::floor((y_m - plan.origin.y_m) / plan.resolution_m));
  for (int dr = -cells; dr <= cells; ++dr) {
    for (int dc = -cells; dc <= cells; ++dc) {
      const int c = col + dc, r = plan.height - 1 - (row_from_bottom + dr);
      if (c >= 0 && c < plan.width && r >= 0 && r < plan.height && plan.at(r, c) >= 0.5f) return true;
    }
  }
  return false;
}

TEST_F(ReferenceMapTest, TheRenderedMapLiesOnTheWallsOfTheFloorPlanTheScansWereCastIn) {
  const std::optional<ReferenceMap> rendered = LoadReferenceMap(spec_, true, Cache());
  ASSERT_TRUE(rendered);
  // The truth the simulator cast its rays in, made by the floor-plan generator, not by the mapper.
  const ev::SimulationOptions options = ev::SimulationOptionsFromJson(spec_.sequence.entry.simulation);
  const ev::OccupancyGrid plan = ev::GenerateFloorPlan(options.floor_plan).grid;
  const ev::OccupancyGrid& map = rendered->grid;
  std::size_t occupied = 0, occupied_near_walls = 0, occupied_on_walls = 0, free = 0, free_inside_walls = 0;
  for (int r = 0; r < map.height; ++r) {
    for (int c = 0; c < map.width; ++c) {
      const float p = map.at(r, c);
      const double x = map.origin.x_m + (c + 0.5) * map.resolution_m;
      const double y = map.origin.y_m + (map.height - 1 - r + 0.5) * map.resolution_m;
      if (p >= 0.65f) {
        ++occupied;
        occupied_near_walls += NearWall(plan, x, y, 1);
        occupied_on_walls += NearWall(plan, x, y, 0);
      } else if (!ev::OccupancyGrid::IsUnknown(p) && p <= 0.196f) {
        ++free;
        free_inside_walls += NearWall(plan, x, y, 0);
      }
    }
  }
  std::cout << "[ reference map ] of " << occupied << " occupied cells " << occupied_near_walls
            << " within a cell of a "
            << "wall, " << occupied_on_walls << " on a wall cell; " << free_inside_walls << " of " << free
            << " free cells inside a wall\n";
  ASSERT_GT(occupied, 200u);
  ASSERT_GT(free, 5000u);
  // The scans carry 1 cm of simulated range noise: every hit is on the wall's face, within a 5 cm cell.
  EXPECT_GE(static_cast<double>(occupied_near_walls), 0.99 * static_cast<double>(occupied));
  // The plan's walls start on cell boundaries, so a hit lands in the wall's first cell or in the free
  // cell before it about equally often (measured: 685 of 1088); a map one cell off would have almost none.
  EXPECT_GE(static_cast<double>(occupied_on_walls), 0.4 * static_cast<double>(occupied));
  // A beam passes along the wall face it ends on: a free cell may graze a wall cell, never more than a few.
  EXPECT_LE(static_cast<double>(free_inside_walls), 0.01 * static_cast<double>(free));
}

TEST_F(ReferenceMapTest, RenderedFromTheCleanScansAtTheReferencePosesAndCached) {
  const std::optional<ReferenceMap> first = LoadReferenceMap(spec_, true, Cache());
  ASSERT_TRUE(first);
  EXPECT_EQ(first->source, "rendered");
  EXPECT_FALSE(first->from_cache);
  EXPECT_TRUE(first->cache_problem.empty()) << first->cache_problem;
  EXPECT_EQ(first->file, Cache() / (ReferenceMapCacheName(spec_) + ".yaml"));
  const ev::OccupancyGrid expected = ExpectedMap(60, 0.05);
  EXPECT_EQ(first->grid.width, expected.width);
  EXPECT_EQ(first->grid.height, expected.height);
  EXPECT_EQ(Classes(first->grid), Classes(expected));

  // A run with range noise and odometry noise reads the same map: the reference uses the clean scans.
  RunSpec noisy = spec_;
  noisy.noise.name = "noisy";
  noisy.noise.range = ev::RangeNoise{};
  noisy.noise.range->sigma_m = 0.2;
  noisy.noise.odometry = ev::OdometryNoise{};
  noisy.noise.odometry->alpha1 = 0.2;
  const std::optional<ReferenceMap> second = LoadReferenceMap(noisy, true, Cache());
  ASSERT_TRUE(second);
  EXPECT_TRUE(second->from_cache);
  EXPECT_EQ(second->grid.cells, first->grid.cells);

  // Another cell size is another entry, rendered at that size.
  RunSpec coarse = spec_;
  coarse.evaluation.map_resolution_m = 0.1;
  const std::optional<ReferenceMap> third = LoadReferenceMap(coarse, true, Cache());
  ASSERT_TRUE(third);
  EXPECT_FALSE(third->from_cache);
  EXPECT_DOUBLE_EQ(third->grid.resolution_m, 0.1);
  EXPECT_EQ(Classes(third->grid), Classes(ExpectedMap(60, 0.1)));
}

TEST_F(ReferenceMapTest, WithoutAReferenceThereIsNoMap) {
  EXPECT_FALSE(LoadReferenceMap(spec_, false, Cache()));
  EXPECT_FALSE(fs::exists(Cache()));
}

TEST_F(ReferenceMapTest, ADamagedEntryIsRenderedAgain) {
  const std::optional<ReferenceMap> first = LoadReferenceMap(spec_, true, Cache());
  ASSERT_TRUE(first);
  fs::path pgm = first->file;
  pgm.replace_extension(".pgm");
  std::ofstream(pgm, std::ios::trunc) << "P5\n3 3\n255\n";  // truncated image
  const std::optional<ReferenceMap> again = LoadReferenceMap(spec_, true, Cache());
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->from_cache);
  EXPECT_EQ(again->grid.cells, first->grid.cells);
  // A key file for another key is not this entry either.
  fs::path key_file = first->file;
  key_file.replace_extension(".key.json");
  std::ofstream(key_file, std::ios::trunc) << "{\"another\": \"key\"}\n";
  EXPECT_FALSE(LoadReferenceMap(spec_, true, Cache())->from_cache);
}

TEST_F(ReferenceMapTest, ConcurrentWorkersRenderOnceAndReadTheSameMap) {
  constexpr int kWorkers = 4;
  std::vector<pid_t> children;
  for (int i = 0; i < kWorkers; ++i) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      int code = 3;
      try {
        const std::optional<ReferenceMap> map = LoadReferenceMap(spec_, true, Cache());
        std::ofstream out(dir_ / ("worker" + std::to_string(i) + ".txt"));
        out << (map->from_cache ? "cached" : "rendered") << "\n";
        for (float p : map->grid.cells) out << p << " ";
        code = out ? 0 : 4;
      } catch (...) {
      }
      ::_exit(code);
    }
    children.push_back(child);
  }
  int rendered = 0;
  std::string cells;
  for (int i = 0; i < kWorkers; ++i) {
    int status = 0;
    ASSERT_EQ(::waitpid(children[i], &status, 0), children[i]);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
    std::ifstream in(dir_ / ("worker" + std::to_string(i) + ".txt"));
    std::string how, rest;
    std::getline(in, how);
    std::getline(in, rest);
    rendered += how == "rendered";
    if (cells.empty()) cells = rest;
    EXPECT_EQ(rest, cells) << "worker " << i;
  }
  EXPECT_EQ(rendered, 1);
  // One entry, complete, and no staging folder left behind.
  std::vector<std::string> names;
  for (const auto& item : fs::directory_iterator(Cache())) names.push_back(item.path().filename().string());
  std::sort(names.begin(), names.end());
  const std::string stem = ReferenceMapCacheName(spec_);
  EXPECT_EQ(names, (std::vector<std::string>{stem + ".key.json", stem + ".lock", stem + ".pgm", stem + ".yaml"}));
}

TEST_F(ReferenceMapTest, ACatalogMapFileIsUsedInsteadAtTheEvaluationCellSize) {
  ev::OccupancyGrid room(20, 10, 0.1, {1.0, 2.0, 0.0}, 0.0f);
  for (int c = 0; c < 20; ++c) room.at(0, c) = 1.0f;
  ev::WriteMapServer(room, dir_ / "room.yaml");
  spec_.sequence.entry.reference_map_path = (dir_ / "room.yaml").string();
  const std::optional<ReferenceMap> map = LoadReferenceMap(spec_, false, Cache());
  ASSERT_TRUE(map);
  EXPECT_EQ(map->source, "file");
  EXPECT_EQ(map->file, dir_ / "room.yaml");
  EXPECT_DOUBLE_EQ(map->grid.resolution_m, 0.05);
  EXPECT_EQ(map->grid.width, 40);
  EXPECT_EQ(map->grid.at(0, 0), 1.0f);
  EXPECT_EQ(map->grid.at(5, 5), 0.0f);
  EXPECT_FALSE(fs::exists(Cache()));  // nothing rendered, nothing cached
  spec_.sequence.entry.reference_map_path = (dir_ / "missing.yaml").string();
  EXPECT_THROW(LoadReferenceMap(spec_, true, Cache()), ev::InputError);
}

TEST_F(ReferenceMapTest, AnUnwritableCacheStillGivesTheMap) {
  slamsweep::testing::WriteFile(dir_ / "not-a-folder", "x");
  const std::optional<ReferenceMap> map = LoadReferenceMap(spec_, true, dir_ / "not-a-folder" / "cache");
  ASSERT_TRUE(map);
  EXPECT_FALSE(map->cache_problem.empty());
  EXPECT_EQ(Classes(map->grid), Classes(ExpectedMap(60, 0.05)));
}

}  // namespace
}  // namespace slamsweep::orchestrator
