#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slamsweep::evaluator::inline core {

/// The running program's file, symbolic links resolved: /proc/self/exe, else (a sandbox without /proc)
/// the path it was started by (the auxiliary vector's AT_EXECFN) from the working folder it started in.
/// Empty when neither is known.
std::filesystem::path RunningProgram();

/// The folders where slamsweep's helper programs (slamsweep-maps, slamsweep-sweep) and format
/// modules (slamsweep-rawlog.so, slamsweep-rosbag.so) are looked for, in this order:
///  - $SLAMSWEEP_LIBEXEC_DIR alone, when it is set and not empty;
///  - the folder of the running program: the build tree (build/slamsweep and its helpers side
///    by side) and a flat installation;
///  - that folder's ../lib/slamsweep: an installation under a prefix (bin/slamsweep,
///    lib/slamsweep/slamsweep-sweep, ...);
///  - the build tree this code was compiled in, so that test programs deeper in it find them.
std::vector<std::filesystem::path> LibexecSearchDirs();

/// The first existing `name` in LibexecSearchDirs(); std::nullopt when there is none.
std::optional<std::filesystem::path> FindLibexecFile(std::string_view name);

/// An installed slamsweep's data (dataset catalog, example sweeps, roster manifests, Cartographer's
/// options): `relative` under PREFIX/share/slamsweep, found beside the running program (PREFIX/bin/slamsweep
/// or a helper or roster driver in PREFIX/lib/slamsweep). std::nullopt in a build tree, whose programs
/// use the source and build paths compiled into them.
std::optional<std::filesystem::path> FindInstalledData(std::string_view relative);

/// "looked in A, B and C (set SLAMSWEEP_LIBEXEC_DIR to choose the folder)": the end of the
/// message that reports a missing helper or module.
std::string DescribeLibexecSearch();

}  // namespace slamsweep::evaluator::inline core
