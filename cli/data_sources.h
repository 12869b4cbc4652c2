#pragma once

#include <filesystem>
#include <string>

#include "evaluator/sequence/catalog.h"
#include "evaluator/sequence/sequence.h"
#include "evaluator/sequence/sequence_file.h"

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
/// `read_options` apply to a file argument (catalog entries carry their own).
evaluator::Sequence LoadSequenceArgument(const std::string& argument, const CatalogLocation& location,
                                         const evaluator::SequenceReadOptions& read_options = {});

}  // namespace slamsweep::cli
