// Runtime options of the sanitizer builds (cmake/SlamsweepSanitize.cmake links this into every program and
// module), so that every slamsweep process has them however it was started. Environment variables
// (ASAN_OPTIONS, LSAN_OPTIONS, UBSAN_OPTIONS) still override them.

#include <unistd.h>

extern "C" {

// Leaks are reported at exit (LeakSanitizer is part of AddressSanitizer on Linux), where /proc is mounted:
// LeakSanitizer stops the threads it finds in /proc/self/task, and without it ends a clean program with a
// fatal error. A sandbox without /proc (SLAMSWEEP_SANDBOX_PROC=none, or where none can be mounted) runs its
// instrumented programs (slamsweep-sandbox-init, the drivers) with every check but the leak check. Without
// /proc the runtime cannot read the environment either, so ASAN_OPTIONS cannot turn it off there.
const char* __asan_default_options() {
  return ::access("/proc/self/task", R_OK) == 0 ? "detect_leaks=1:check_initialization_order=1"
                                                : "detect_leaks=0:check_initialization_order=1";
}

// A report prints where it happened; every finding ends the program with an error.
const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

// Third-party libraries only. Each line: what is reported and why it is not ours to fix.
const char* __lsan_default_suppressions() {
  // GMapping (openslam_gmapping, built by scripts/install-slam.sh and linked into slamsweep-slam-gmapping):
  // processScan keeps a new RangeReading in every trajectory node, which the node's destructor never deletes,
  // and patch grids of its particles' maps (Array2D) are lost inside its own map code. Upstream's, at exit.
  return "leak:GMapping::\n"
         // BreezySLAM (linked into tinyslam_crosscheck_test only): CoreSLAM's constructor copies the Laser with
         // new, and its destructor never deletes it (48 bytes per RMHC_SLAM object).
         "leak:CoreSLAM::CoreSLAM\n";
}

// Third-party libraries only, as above: reports of AddressSanitizer's interceptors (memcpy...) called from them.
const char* __asan_default_suppressions() {
  // librosbag parses record headers with ros::Header::parse (Debian's libcpp_common, roscpp_core), which trusts
  // their field lengths and copies up to 512 KiB from beyond the buffer when one runs past the header
  // (tests/fuzz/corpus/rosbag/librosbag-header-overread-*.bag).
  // slamsweep reads ROS 1 bags only in a contained child (evaluator/sequence_io/contained_read.h), so the
  // over-read ends that child or the library refuses the record: the read fails with an InputError.
  return "interceptor_via_fun:ros::Header::parse\n";
}

}  // extern "C"
