#include "evaluator/sequence_io/contained_read.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "evaluator/core/gzip_inflate.h"
#include "evaluator/core/input_error.h"
#include "evaluator/sequence_io/sequence_codec.h"

#if defined(__SANITIZE_ADDRESS__)
#define SLAMSWEEP_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SLAMSWEEP_ASAN 1
#endif
#endif
#if defined(SLAMSWEEP_ASAN)
#include <sanitizer/asan_interface.h>
#include <sanitizer/common_interface_defs.h>
#endif

namespace slamsweep::evaluator::inline sequence_io {
namespace {

/// How the child's read ended: the first byte of what it sends.
/// kCrashed (AddressSanitizer builds): a deadly signal the sanitizer caught, with its kind of fault.
enum class ChildStatus : char {
  kOk = 'O',
  kInputError = 'I',
  kInternalError = 'E',
  kOutOfMemory = 'M',
  kCrashed = 'C'
};

std::string MiB(std::uintmax_t bytes) {
  return fmt::format("{:.0f} MiB", std::ceil(static_cast<double>(bytes) / (1024.0 * 1024.0)));
}

/// The process's data segment (VmData: what RLIMIT_DATA counts), or nothing without /proc.
std::optional<std::uintmax_t> DataSegmentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.starts_with("VmData:")) return std::stoull(line.substr(7)) * 1024;
  }
  return std::nullopt;
}

bool WriteAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

#if defined(SLAMSWEEP_ASAN)
/// The pipe of a child reader, for the death callback below.
int child_pipe = -1;

/// AddressSanitizer ends the process when an allocation fails (where std::bad_alloc would be thrown): a
/// refused allocation is then reported as the memory limit, like std::bad_alloc without the sanitizer. It
/// also catches deadly signals (SIGSEGV...) and exits instead of dying by them: such a report is a crash of the
/// library, as the signal is without the sanitizer. Any other report (a memory error the instrumentation saw)
/// goes on to end the process, which the parent reports as a failure of ours.
/// When the runtime's own mmap fails while it reports, it dies without a description ("ERROR: Failed to mmap");
/// then the data segment at its limit says it was the memory limit. Raw reads into the stack: the heap is full.
bool DataSegmentAtItsLimit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_DATA, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return false;
  const int fd = ::open("/proc/self/status", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  std::array<char, 4096> text{};
  const ssize_t size = ::read(fd, text.data(), text.size() - 1);
  ::close(fd);
  if (size <= 0) return false;
  const char* line = std::strstr(text.data(), "VmData:");
  if (line == nullptr) return false;
  const std::uintmax_t data_bytes = std::strtoull(line + 7, nullptr, 10) * 1024;
  constexpr std::uintmax_t kHeadroom = std::uintmax_t{64} << 20;  // what a failed report may have left unused
  return data_bytes + kHeadroom >= limit.rlim_cur;
}

void ReportMemoryLimitOnDeath() {
  const std::string_view report = __asan_get_report_description();
  if (report == "out-of-memory" || report == "allocation-size-too-big" || report == "rss-limit-exceeded" ||
      (report.empty() && DataSegmentAtItsLimit())) {
    const char status = static_cast<char>(ChildStatus::kOutOfMemory);
    if (::write(child_pipe, &status, 1) == 1) ::_exit(0);
  }
  // The kinds of AddressSanitizer's deadly-signal reports. No allocation here: the heap may be what broke.
  constexpr std::array<std::string_view, 7> kDeadlySignal = {
      "signal", "stack-overflow", "null-deref", "wild-jump", "wild-addr-write", "wild-addr-read", "wild-addr"};
  if (std::find(kDeadlySignal.begin(), kDeadlySignal.end(), report) != kDeadlySignal.end()) {
    std::array<char, 64> message{};
    message[0] = static_cast<char>(ChildStatus::kCrashed);
    const std::size_t size = std::min(report.size(), message.size() - 1);
    std::copy_n(report.begin(), size, message.begin() + 1);
    if (WriteAll(child_pipe, std::string_view(message.data(), size + 1))) ::_exit(0);
  }
}
#endif

/// The child: limits, the read, its result down the pipe; never returns.
[[noreturn]] void RunChild(int fd, const ReaderLimits& limits, std::optional<std::uintmax_t> data_bytes,
                           const std::function<ModuleOutcome(Sequence&)>& read) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGCHLD, SIGXCPU}) ::signal(signal_number, SIG_DFL);
  const auto cpu = static_cast<rlim_t>(std::ceil(limits.cpu_s));
  const rlimit cpu_limit{cpu, cpu + 1};
  ::setrlimit(RLIMIT_CPU, &cpu_limit);
  const rlimit no_core{0, 0};  // a crash of the library is reported, not dumped into the working folder
  ::setrlimit(RLIMIT_CORE, &no_core);
  if (data_bytes) {
    const rlimit data_limit{*data_bytes + limits.memory_bytes, *data_bytes + limits.memory_bytes};
    ::setrlimit(RLIMIT_DATA, &data_limit);
  }
#if defined(SLAMSWEEP_ASAN)
  child_pipe = fd;
  __sanitizer_set_death_callback(ReportMemoryLimitOnDeath);
#endif
  std::string message(1, static_cast<char>(ChildStatus::kInternalError));
  try {
    Sequence sequence;
    const ModuleOutcome outcome = read(sequence);
    if (outcome.kind == ModuleOutcome::Kind::kOk) {
      message = static_cast<char>(ChildStatus::kOk) + EncodeSequence(sequence);
    } else if (outcome.kind == ModuleOutcome::Kind::kInputError) {
      message = static_cast<char>(ChildStatus::kInputError) + outcome.message;
    } else {
      // The module turns every exception into a message: std::bad_alloc's is its name.
      const bool memory = outcome.message == std::bad_alloc().what();
      message = static_cast<char>(memory ? ChildStatus::kOutOfMemory : ChildStatus::kInternalError) + outcome.message;
    }
  } catch (const std::bad_alloc&) {
    message.assign(1, static_cast<char>(ChildStatus::kOutOfMemory));
  } catch (const std::exception& error) {
    message.assign(1, static_cast<char>(ChildStatus::kInternalError));
    message += error.what();
  }
  // _exit: the parent's atexit handlers and static objects are the parent's business.
  ::_exit(WriteAll(fd, message) ? 0 : 1);
}

/// Everything the child sends, until it closes the pipe or `deadline`; nothing when the deadline came first.
std::optional<std::string> ReadUntilClosed(int fd, std::chrono::steady_clock::time_point deadline) {
  std::string received;
  std::array<char, 1 << 16> buffer{};
  while (true) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd entry{fd, POLLIN, 0};
    const int ready = ::poll(&entry, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    if (ready <= 0) continue;
    const ssize_t got = ::read(fd, buffer.data(), buffer.size());
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw std::runtime_error(std::string("reading from a reader process: ") + std::strerror(errno));
    if (got == 0) return received;
    received.append(buffer.data(), static_cast<std::size_t>(got));
  }
}

std::string CrashMessage(std::string_view library, std::string_view how) {
  return fmt::format("{} crashed reading it ({}): the file is damaged or not what its name says", library, how);
}

/// The child's wait status and the CPU time it used.
std::pair<int, double> Reap(pid_t pid) {
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  const auto seconds = [](const timeval& time) { return static_cast<double>(time.tv_sec) + 1e-6 * time.tv_usec; };
  return {status, seconds(usage.ru_utime) + seconds(usage.ru_stime)};
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { Close(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void Close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

}  // namespace

ReaderLimits LimitsForContent(std::uintmax_t content_bytes) {
  constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;
  ReaderLimits limits;
  limits.memory_bytes = 32 * kMiB + 16 * content_bytes;
#if defined(SLAMSWEEP_ASAN)
  limits.memory_bytes += 1024 * kMiB;
#endif
  limits.cpu_s = 10.0 + 2.0 * static_cast<double>(content_bytes) / static_cast<double>(kMiB);
  limits.wall_s = 4.0 * limits.cpu_s + 10.0;
  return limits;
}

std::uintmax_t ContentBytes(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return 0;
  std::ifstream in(path, std::ios::binary);
  std::array<char, 2> magic{};
  in.read(magic.data(), 2);
  if (size < 18 || !HasGzipMagic(std::string_view(magic.data(), 2))) return size;
  std::array<unsigned char, 4> tail{};
  in.seekg(static_cast<std::streamoff>(size - 4));
  in.read(reinterpret_cast<char*>(tail.data()), 4);
  const std::uintmax_t claimed = tail[0] | tail[1] << 8 | tail[2] << 16 | std::uintmax_t{tail[3]} << 24;
  return std::clamp<std::uintmax_t>(claimed, size, GzipInflateCap(static_cast<std::size_t>(size)));
}

Sequence ReadContained(const std::filesystem::path& file, std::string_view library, const ReaderLimits& limits,
                       const std::function<ModuleOutcome(Sequence&)>& read) {
  static std::mutex one_at_a_time;
  const std::lock_guard lock(one_at_a_time);
  std::array<int, 2> ends{};
  if (::pipe2(ends.data(), O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  Fd from_child(ends[0]);
  Fd to_parent(ends[1]);
  const std::optional<std::uintmax_t> data_bytes = DataSegmentBytes();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    from_child.Close();
    RunChild(to_parent.get(), limits, data_bytes, read);
  }
  to_parent.Close();
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::milliseconds(static_cast<long long>(std::ceil(limits.wall_s * 1000.0)));
  const std::optional<std::string> received = ReadUntilClosed(from_child.get(), deadline);
  if (!received) ::kill(pid, SIGKILL);
  const auto [status, cpu_s] = Reap(pid);
  if (!received) {
    throw InputError(Located(file, 0,
                             fmt::format("{} did not finish reading it within {:.0f} s (the limit for a file "
                                         "of this size)",
                                         library, limits.wall_s)));
  }
  if (WIFSIGNALED(status)) {
    const int signal_number = WTERMSIG(status);
    if (signal_number == SIGXCPU || (signal_number == SIGKILL && cpu_s >= std::floor(limits.cpu_s))) {
      throw InputError(Located(file, 0,
                               fmt::format("{} took more than {:.0f} s of CPU time reading it (the limit for "
                                           "a file of this size): the file is damaged or hostile",
                                           library, std::ceil(limits.cpu_s))));
    }
    throw InputError(Located(
        file, 0, CrashMessage(library, fmt::format("signal {}: {}", signal_number, ::strsignal(signal_number)))));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || received->empty()) {
    throw std::runtime_error(fmt::format("{}: the process reading it with {} ended (status {}) without a result",
                                         file.string(), library, status));
  }
  const std::string_view text = std::string_view(*received).substr(1);
  switch (static_cast<ChildStatus>(received->front())) {
    case ChildStatus::kOk:
      return DecodeSequence(text);
    case ChildStatus::kInputError:
      throw InputError(std::string(text));
    case ChildStatus::kOutOfMemory:
      throw InputError(Located(file, 0,
                               fmt::format("{} needs more than {} of memory to read it, the limit for a file "
                                           "of this size: the file is damaged or declares more data than it "
                                           "holds",
                                           library, MiB(limits.memory_bytes))));
    case ChildStatus::kCrashed:
      throw InputError(
          Located(file, 0, CrashMessage(library, fmt::format("a deadly signal, AddressSanitizer: {}", text))));
    case ChildStatus::kInternalError:
      break;
  }
  throw std::runtime_error(std::string(text));
}

}  // namespace slamsweep::evaluator::inline sequence_io
