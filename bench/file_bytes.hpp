// A whole file in memory, as the benchmark's loaders start from it.
#pragma once

#include <cstddef>
#include <memory>

namespace bench {

/// The bytes of the file at `path` (and their count in `size`), followed by a NUL that
/// `size` leaves out, or nullptr when the file cannot be read. A writable buffer: the peers
/// parse it in place, rapidxml up to the NUL.
std::unique_ptr<char[]> read_file(const char* path, size_t& size);

} // namespace bench
