// A whole file in memory, as the benchmark's loaders start from it.
#pragma once

#include <cstddef>
#include <memory>

namespace bench {

/// The bytes of the file at `path` (and their count in `size`), or nullptr when it cannot
/// be read. A writable buffer: pugixml parses it in place.
std::unique_ptr<char[]> read_file(const char* path, size_t& size);

} // namespace bench
