#include "cli/data_sources.h"

#include <cstdlib>
#include <system_error>

#include "evaluator/core/input_error.h"
#include "evaluator/core/installation.h"
#include "evaluator/sequence_io/sequence_file.h"

namespace slamsweep::cli {

namespace ev = slamsweep::evaluator;

namespace {

std::string Environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

}  // namespace

CatalogLocation FindCatalog(const std::string& catalog_option) {
  CatalogLocation location;
  const std::string catalog_env = Environment("SLAMSWEEP_CATALOG");
  // An installed slamsweep reads its installed catalog; a build tree the repository's.
  const auto installed = ev::FindInstalledData("configs/datasets.yaml");
  location.catalog = !catalog_option.empty() ? std::filesystem::path(catalog_option)
                     : !catalog_env.empty()  ? std::filesystem::path(catalog_env)
                     : installed             ? *installed
                                             : std::filesystem::path(SLAMSWEEP_DEFAULT_CATALOG);
  const std::string shared_env = Environment("SLAMSWEEP_SHARED");
  location.shared_root = !shared_env.empty() ? shared_env : std::string(SLAMSWEEP_DEFAULT_SHARED);
  return location;
}

ev::Sequence LoadSequenceArgument(const std::string& argument, const CatalogLocation& location,
                                  const ev::SequenceReadOptions& read_options, std::optional<ev::OdometryMode> odometry,
                                  std::optional<ev::GroundTruthKind> ground_truth) {
  std::error_code error;
  if (std::filesystem::is_regular_file(argument, error)) {
    ev::SequenceReadOptions options = read_options;
    if (ground_truth) {
      ev::CatalogEntry declared;
      declared.ground_truth = *ground_truth;
      options.carmen.logged_pose_is_reference = ev::LoggedPoseIsReference(declared);
    }
    if (odometry == ev::OdometryMode::kReference && !options.carmen.logged_pose_is_reference) {
      throw ev::InputError("--odometry reference: " + argument +
                           " is declared raw (--ground-truth): its logged pose is its only odometry");
    }
    options.carmen.odometry = odometry.value_or(ev::OdometryMode::kRecorded);
    options.carmen.require_recorded_odometry = odometry.has_value();
    return ev::ReadSequence(argument, options);
  }
  ev::Catalog catalog;
  try {
    catalog = ev::ReadCatalog(location.catalog);
  } catch (const ev::InputError& catalog_error) {
    throw ev::InputError(argument + ": no such file, and the catalog cannot be read to look the name up (" +
                         catalog_error.what() + ")");
  }
  for (const ev::CatalogEntry& entry : catalog.entries) {
    if (entry.name == argument) {
      ev::CatalogEntry chosen = entry;
      if (ground_truth) chosen.ground_truth = *ground_truth;
      if (odometry) {
        if (*odometry == ev::OdometryMode::kReference && !ev::OdometryModeApplies(entry)) {
          throw ev::InputError("--odometry reference: sequence '" + argument +
                               "' is not a corrected CARMEN log; it has only its recorded odometry");
        }
        chosen.odometry = odometry;
      }
      return ev::LoadCatalogSequence(chosen, {{"SHARED", location.shared_root.string()}});
    }
  }
  std::string known;
  for (const ev::CatalogEntry& entry : catalog.entries) known += (known.empty() ? "" : ", ") + entry.name;
  throw ev::InputError(argument + ": no such file, and no sequence of that name in the catalog " +
                       location.catalog.string() + " (known: " + known + ")");
}

}  // namespace slamsweep::cli
