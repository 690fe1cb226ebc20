#include "floor_scan.hpp"

#include <cstring>

namespace bench {
namespace {

/// The offset of the first `byte` in `text[from, size)`, or `size`: eight bytes at a time,
/// each byte equal to it flagged by the usual zero-byte test.
size_t find(const char* text, size_t from, size_t size, char byte) {
    const uint64_t ones = 0x0101010101010101ull, high = 0x8080808080808080ull;
    const uint64_t pattern = ones * static_cast<unsigned char>(byte);
    size_t i = from;
    for (; i + 8 <= size; i += 8) {
        uint64_t word;
        std::memcpy(&word, text + i, 8);
        uint64_t x = word ^ pattern;
        uint64_t found = (x - ones) & ~x & high;
        if (found != 0) {
            return i + static_cast<size_t>(__builtin_ctzll(found) / 8);
        }
    }
    while (i < size && text[i] != byte) {
        ++i;
    }
    return i;
}

bool is_separator(char c) {
    return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == ',';
}

/// The number at `text[i]` (before `end`), converted in one step; false when it is not one
/// that step takes: [sign] digits [. digits] [e|E [sign] digits], at most 2^24 as its
/// digits and a power of ten of at most 10^10 either way.
bool exact_number(const char* text, size_t& i, size_t end, float& value) {
    bool negative = text[i] == '-';
    if (text[i] == '-' || text[i] == '+') {
        ++i;
    }
    uint64_t mantissa = 0;
    size_t start = i, point = 0;
    bool has_point = false;
    for (; i < end; ++i) {
        unsigned digit = static_cast<unsigned>(static_cast<unsigned char>(text[i]) - '0');
        if (digit < 10) {
            mantissa = mantissa * 10 + digit;
        } else if (text[i] == '.' && !has_point) {
            has_point = true;
            point = i;
        } else {
            break;
        }
    }
    size_t digits = i - start - (has_point ? 1 : 0);
    if (digits == 0 || digits > 19 || mantissa > (1u << 24)) {
        return false;
    }
    int scale = has_point ? -static_cast<int>(i - point - 1) : 0;
    if (i < end && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        bool negative_exponent = i < end && text[i] == '-';
        if (i < end && (text[i] == '-' || text[i] == '+')) {
            ++i;
        }
        int exponent = 0;
        for (; i < end && static_cast<unsigned>(static_cast<unsigned char>(text[i]) - '0') < 10u; ++i) {
            exponent = exponent * 10 + (text[i] - '0');
        }
        scale += negative_exponent ? -exponent : exponent;
    }
    if (scale < -10 || scale > 10) {
        return false;
    }
    static const float powers[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                   1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
    float magnitude = static_cast<float>(static_cast<uint32_t>(mantissa));
    float power = powers[scale < 0 ? -scale : scale];
    value = scale < 0 ? magnitude / power : magnitude * power;
    if (negative) {
        value = -value;
    }
    return true;
}

} // namespace

FloorCount floor_scan(const char* text, size_t size) {
    FloorCount count;
    size_t after_tag = 0;
    for (;;) {
        size_t open = find(text, after_tag, size, '<');
        for (size_t i = after_tag;;) {
            while (i < open && is_separator(text[i])) {
                ++i;
            }
            float value = 0;
            if (i >= open || !exact_number(text, i, open, value)) {
                break;
            }
            count.numbers += 1;
            count.sum += value;
        }
        if (open + 1 >= size) {
            return count;
        }
        count.start_tags += text[open + 1] != '/';
        size_t close = find(text, open + 1, size, '>');
        if (close >= size) {
            return count;
        }
        after_tag = close + 1;
    }
}

} // namespace bench
