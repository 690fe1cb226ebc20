#include "peer_values.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace bench::peer {
namespace {

[[noreturn]] void refuse(std::string_view text, const char* what) {
    throw ValueError("'" + std::string(text) + "' is not " + what);
}

/// `text` without one leading `+` that precedes a digit (or the dot of `+.5`), which
/// std::from_chars does not take; a `+` before anything else is refused.
std::string_view without_plus(std::string_view text, const char* what) {
    if (text.empty() || text[0] != '+') {
        return text;
    }
    if (text.size() < 2 || !((text[1] >= '0' && text[1] <= '9') || text[1] == '.')) {
        refuse(text, what);
    }
    return text.substr(1);
}

template <typename Int>
Int to_integer(std::string_view digits, int base, std::string_view text, const char* what) {
    Int value{};
    auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
    if (error != std::errc() || end != digits.data() + digits.size()) {
        refuse(text, what);
    }
    return value;
}

/// std::from_chars reports both overflow and underflow as out of range; strtof tells them
/// apart (an underflow is a zero or a subnormal, as box2scene reads it).
float out_of_range_float(std::string_view text) {
    float value = std::strtof(std::string(text).c_str(), nullptr);
    if (!std::isfinite(value)) {
        throw ValueError(std::string(text) + " is too large for a 32-bit float");
    }
    return value;
}

} // namespace

std::string_view trim(std::string_view text) {
    size_t first = 0, last = text.size();
    while (first < last && is_xml_space(text[first])) {
        ++first;
    }
    while (last > first && is_xml_space(text[last - 1])) {
        --last;
    }
    return text.substr(first, last - first);
}

bool is_word(std::string_view text, std::string_view lower) {
    if (text.size() != lower.size()) {
        return false;
    }
    for (size_t i = 0; i < lower.size(); ++i) {
        if ((static_cast<unsigned char>(text[i]) | 0x20) != static_cast<unsigned char>(lower[i])) {
            return false;
        }
    }
    return true;
}

float to_float(std::string_view text) {
    std::string_view digits = without_plus(text, "a number");
    float value = 0;
    auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || digits.empty() ||
        (error != std::errc() && error != std::errc::result_out_of_range)) {
        refuse(text, "a number");
    }
    if (error == std::errc::result_out_of_range) {
        return out_of_range_float(digits);
    }
    if (!std::isfinite(value)) { // from_chars reads "inf" and "nan"; the format does not
        refuse(text, "a finite number");
    }
    return value;
}

b2s_vec2 to_vector2(std::string_view text) {
    if (text.empty()) {
        return b2s_vec2{0, 0};
    }
    std::string_view x, y;
    size_t comma = text.find(',');
    if (comma != std::string_view::npos) {
        x = trim(text.substr(0, comma));
        y = trim(text.substr(comma + 1));
        if (y.find(',') != std::string_view::npos) {
            refuse(text, "a vector: expected two numbers");
        }
    } else {
        size_t end_x = 0;
        while (end_x < text.size() && !is_xml_space(text[end_x])) {
            ++end_x;
        }
        x = text.substr(0, end_x);
        y = trim(text.substr(end_x));
        for (char c : y) {
            if (is_xml_space(c)) {
                refuse(text, "a vector: expected two numbers");
            }
        }
    }
    if (x.empty() || y.empty()) {
        refuse(text, "a vector: expected two numbers");
    }
    return b2s_vec2{to_float(x), to_float(y)};
}

bool to_bool(std::string_view text) {
    if (text == "1" || is_word(text, "true")) {
        return true;
    }
    if (text == "0" || is_word(text, "false")) {
        return false;
    }
    refuse(text, "a boolean: expected true or false");
}

uint32_t to_id(std::string_view text) {
    uint32_t value = to_integer<uint32_t>(without_plus(text, "an ID"), 10, text, "an ID");
    if (value == UINT32_MAX) {
        refuse(text, "an ID in range");
    }
    return value;
}

uint32_t to_bits(std::string_view text) {
    bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
    std::string_view digits = hex ? text.substr(2) : without_plus(text, "a bit mask");
    uint64_t value = to_integer<uint64_t>(digits, hex ? 16 : 10, text, "a bit mask");
    if (value > UINT32_MAX) {
        refuse(text, "32 bits");
    }
    return static_cast<uint32_t>(value);
}

int16_t to_int16(std::string_view text) {
    int32_t value = to_integer<int32_t>(without_plus(text, "a whole number"), 10, text,
                                        "a whole number");
    if (value < INT16_MIN || value > INT16_MAX) {
        refuse(text, "within -32768..32767");
    }
    return static_cast<int16_t>(value);
}

} // namespace bench::peer
