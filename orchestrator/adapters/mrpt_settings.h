#pragma once
// What the MRPT adapters write into MRPT's configuration templates (no run-time dependencies: the
// plan and `slamsweep algorithms` read these too).
#include <cstddef>
#include <string>
#include <vector>

#include "orchestrator/adapters/mrpt_ini.h"
#include "orchestrator/run/run_spec.h"

namespace slamsweep::orchestrator::inline adapters {

/// The configuration templates shipped with Debian's mrpt-apps.
inline constexpr const char* kIcpSlamTemplate =
    "/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic_gridmatch.ini";
inline constexpr const char* kRbpfSlamTemplate = "/usr/share/mrpt/config_files/rbpf-slam/gridmapping_intel.ini";

/// icp-slam's defaults on top of kIcpSlamTemplate, for laser logs like intel's (scans about 1 m and up to
/// 30 deg apart). The template was tuned for MRPT's dense demo log; on intel it diverges (11.6 m APE on
/// 300 scans) for two measured reasons:
/// - icp-slam inserts a scan only after an accepted ICP match (goodness > minICPgoodnessToAccept), and
///   the template inserts only every 2 m / 45 deg. Between insertions a sparse log's scans see mostly
///   unmapped space, ICP is refused, the map stops growing and the robot never relocalises
///   (14 insertions, 267 refused matches in 300 steps). Inserting every 0.5 m / 20 deg keeps the
///   overlap high.
/// - matching against the 5 cm occupancy grid drifts in heading (-6 deg after 40 scans, 0.85 m APE
///   even when every scan is inserted); matching against a points map of the same scans, with the ICP
///   thresholds of MRPT's points-map demo (icp-slam_demo_classic.ini), keeps APE at 0.10 m. The grid
///   is still built: it is the map the adapter reports.
/// - the grid widens its rays with distance (as MRPT's rbpf-slam intel template does), so free space
///   between diverging beams is filled rather than left as faint streaks (the enclosed-areas metric
///   counts the gaps between streaks as pockets).
/// Run parameters override any of these.
std::vector<IniSetting> IcpSlamDefaultSettings();

/// The settings an MRPT SLAM adapter writes into the template, in the order they are applied:
/// quick defaults, then the run's parameters, then what the adapter must control (input, output
/// folder, no windows, no 3D scenes, rbpf-slam's RANDOM_SEED = Seed31(run seed)). A run parameter
/// naming a controlled key is an InputError. `rawlog_name` is the file name in the run's input/ folder;
/// the program runs in raw/, so the settings name "../input/<rawlog_name>" and output folder ".".
std::vector<IniSetting> IcpSlamSettings(const RunSpec& spec, const std::string& rawlog_name);
std::vector<IniSetting> RbpfSlamSettings(const RunSpec& spec, const std::string& rawlog_name, std::size_t scan_count);

/// A file of the run's input/ folder as the program sees it: it runs in raw/, its input is beside it.
std::string FromRawDir(const std::string& input_file);

}  // namespace slamsweep::orchestrator::inline adapters
