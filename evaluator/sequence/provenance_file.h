#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "evaluator/sequence/sequence.h"

namespace slamsweep::evaluator::inline sequence {

/// The provenance of one data file, from a PROVENANCE.txt as kept beside each dataset in
/// shared/datasets: blocks that start with `File: <name> ...`, holding `Key : value` lines whose
/// values may continue on indented lines. From the block of `data_file_name`:
///   source       = "Source repository", "Commit (snapshot)" (hash only) and "Repo path", joined by "; "
///   citation     = "Original provenance"
///   licence_note = "License note"
/// with each value's lines joined and its runs of blanks collapsed to single spaces. nullopt when
/// no block names the file.
std::optional<Provenance> ParseProvenanceText(std::string_view content, std::string_view data_file_name);

/// ParseProvenanceText on `PROVENANCE.txt` in the folder of `data_file`; nullopt when that file is
/// absent or says nothing about `data_file`. An unreadable PROVENANCE.txt is an InputError.
std::optional<Provenance> ReadProvenanceBeside(const std::filesystem::path& data_file);

}  // namespace slamsweep::evaluator::inline sequence
