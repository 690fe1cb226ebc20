#include "file_bytes.hpp"

#include <cstdio>

namespace bench {

std::unique_ptr<char[]> read_file(const char* path, size_t& size) {
    std::FILE* file = std::fopen(path, "rb");
    if (file == nullptr) {
        return nullptr;
    }
    std::unique_ptr<char[]> bytes;
    long length = -1;
    if (std::fseek(file, 0, SEEK_END) == 0 && (length = std::ftell(file)) >= 0 &&
        std::fseek(file, 0, SEEK_SET) == 0) {
        size = static_cast<size_t>(length);
        // new char[n] leaves the bytes uninitialised: the pages are touched once, by fread.
        bytes.reset(new char[size + 1]);
        if (std::fread(bytes.get(), 1, size, file) != size) {
            bytes.reset();
        } else {
            bytes[size] = '\0';
        }
    }
    std::fclose(file);
    return bytes;
}

} // namespace bench
