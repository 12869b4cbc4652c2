#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "evaluator/catalog/catalog.h"
#include "evaluator/sequence/sequence.h"
#include "evaluator/sequence_io/sequence_file.h"

namespace slamsweep::cli {

/// Where the data commands find the dataset catalog and the shared data folder.
struct CatalogLocation {
  /// --catalog, else $SLAMSWEEP_CATALOG, else the installed PREFIX/share/slamsweep/configs/datasets.yaml,
  /// else the repository's configs/datasets.yaml.
  std::filesystem::path catalog;
  /// ${SHARED} in catalog paths: $SLAMSWEEP_SHARED, else the folder configured at build time.
  std::filesystem::path shared_root;
};

/// The location from the environment and the build defaults; `catalog_option` wins when not empty.
CatalogLocation FindCatalog(const std::string& catalog_option);

/// A sequence named on the command line: an existing file (any format ReadSequence knows), else a
/// catalog name. Neither is an InputError naming the argument and the catalog's names.
/// `read_options` apply to a file argument (catalog entries carry their own). `odometry`, when set,
/// is the odometry mode asked for explicitly (a corrected log without an ODOM stream is then an
/// error naming the line); unset, a file is read as the catalog reads its entries by default: with
/// its recorded odometry where it has a stream, else its logged odometry and a warning.
/// `ground_truth`, when set, is the kind of reference the sequence has (a catalog entry's is replaced):
/// for a CARMEN log, relations_only or none declare it raw (catalog LoggedPoseIsReference). Unset, a
/// CARMEN file is read as a corrected log (its logged pose is the reference), which a raw log cannot be
/// told apart from: the safe side, since a corrected log read as raw would hand programs its corrected
/// poses as odometry with no reference to flag it.
evaluator::Sequence LoadSequenceArgument(const std::string& argument, const CatalogLocation& location,
                                         const evaluator::SequenceReadOptions& read_options = {},
                                         std::optional<evaluator::OdometryMode> odometry = std::nullopt,
                                         std::optional<evaluator::GroundTruthKind> ground_truth = std::nullopt);

}  // namespace slamsweep::cli
