#include "evaluator/core/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <utility>

namespace slamsweep::evaluator::inline core {
namespace {

/// Closes the descriptor when the opening is done (the mapping stays valid without it).
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

bool ReadAll(int fd, std::string& out) {
  char buffer[1 << 16];
  while (true) {
    const ssize_t count = ::read(fd, buffer, sizeof(buffer));
    if (count < 0) return false;
    if (count == 0) return true;
    out.append(buffer, static_cast<std::size_t>(count));
  }
}

}  // namespace

std::optional<MappedFile> MappedFile::Open(const std::filesystem::path& path) {
  Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) return std::nullopt;
  struct stat status {};
  if (::fstat(file.fd, &status) != 0) return std::nullopt;
  MappedFile mapped;
  if (S_ISREG(status.st_mode) && status.st_size > 0) {
    const auto size = static_cast<std::size_t>(status.st_size);
    // MAP_POPULATE: the file is read whole anyway; one call maps every page instead of a fault each.
    void* address = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.fd, 0);
    if (address != MAP_FAILED) {
      mapped.mapping_ = static_cast<const char*>(address);
      mapped.size_ = size;
      return mapped;
    }
  }
  if (!ReadAll(file.fd, mapped.read_)) return std::nullopt;
  return mapped;
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : mapping_(std::exchange(other.mapping_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      read_(std::move(other.read_)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    Release();
    mapping_ = std::exchange(other.mapping_, nullptr);
    size_ = std::exchange(other.size_, 0);
    read_ = std::move(other.read_);
  }
  return *this;
}

MappedFile::~MappedFile() { Release(); }

void MappedFile::Release() noexcept {
  if (mapping_ != nullptr) ::munmap(const_cast<char*>(mapping_), size_);
  mapping_ = nullptr;
  size_ = 0;
}

}  // namespace slamsweep::evaluator::inline core
