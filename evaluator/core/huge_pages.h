#pragma once

#include <cstddef>
#include <vector>

namespace slamsweep::evaluator::inline core {

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with transparent huge pages
/// (madvise MADV_HUGEPAGE) before they are first written: a 100,000-pose trajectory then takes a few
/// hundred page faults instead of thousands. Does nothing below 4 MiB; a kernel that declines changes
/// nothing but the page size, never the contents.
void AdviseHugePages(const void* data, std::size_t bytes);

/// The same for the reserved buffer of a vector (its capacity, not just its size).
template <typename T>
void AdviseHugePages(const std::vector<T>& values) {
  AdviseHugePages(values.data(), values.capacity() * sizeof(T));
}

}  // namespace slamsweep::evaluator::inline core
