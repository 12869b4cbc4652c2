// Runtime options of the sanitizer builds (cmake/SlamsweepSanitize.cmake links this into every program and
// module), so that every slamsweep process has them however it was started. Environment variables
// (ASAN_OPTIONS, LSAN_OPTIONS, UBSAN_OPTIONS) still override them.

extern "C" {

// Leaks are reported at exit (LeakSanitizer is part of AddressSanitizer on Linux).
const char* __asan_default_options() { return "detect_leaks=1:check_initialization_order=1"; }

// A report prints where it happened; every finding ends the program with an error.
const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

// Third-party libraries only. Each line: what is reported and why it is not ours to fix.
const char* __lsan_default_suppressions() { return ""; }

}  // extern "C"
