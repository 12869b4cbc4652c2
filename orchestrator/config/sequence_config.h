#pragma once

#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

#include "evaluator/catalog/catalog.h"
#include "orchestrator/config/input_policy.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline config {

/// One entry of a sweep's `sequences:`: a catalog name, {catalog: NAME, name: NEW, max_scans: N}, or an
/// inline catalog entry (plus max_scans). Paths come back resolved (${VARIABLES} replaced, relative
/// paths anchored at the catalog's or the sweep file's folder), and the files must exist: a missing
/// one is an error naming the entry, the file and the entry's download hint. A file outside the
/// policy's roots is a PolicyError, raised before its existence is checked.
SequenceSpec ParseSequenceConfig(const std::filesystem::path& file, YAML::Node node, const std::string& path,
                                 const evaluator::Catalog& catalog, const evaluator::CatalogVariables& variables,
                                 const InputPolicy& policy = {});

}  // namespace slamsweep::orchestrator::inline config
