// The peers' text-to-value conversions, with the semantics of box2scene's
// src/text.rs for every spelling of docs/format.md (std::from_chars does the digits).
// Each takes text already trimmed of XML white space and throws ValueError when it is not
// a value of its type.
#pragma once

#include <box2scene.h>

#include <cstdint>
#include <stdexcept>
#include <string_view>

namespace bench::peer {

/// Why a text is not a value of its type; the loader adds where.
struct ValueError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// XML white space (not Unicode's).
inline bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view text);

/// Whether `text` is `lower` (lower case) in any letter case, as the format compares
/// names and enumeration values (ASCII letters only).
bool is_word(std::string_view text, std::string_view lower);

/// A finite decimal float, rounded correctly to the nearest f32; `+1`, `.5`, `5.` and
/// exponents included, infinities, NaN and values beyond f32 refused.
float to_float(std::string_view text);

/// Two floats separated by white space and/or one comma; empty text is (0, 0).
b2s_vec2 to_vector2(std::string_view text);

/// `true`/`false` in any letter case, or `1`/`0`.
bool to_bool(std::string_view text);

/// A non-negative index (optional `+`), below UINT32_MAX.
uint32_t to_id(std::string_view text);

/// Collision bits, decimal or `0x` hexadecimal, 32 of them.
uint32_t to_bits(std::string_view text);

/// A 16-bit signed int (a group index), optional sign.
int16_t to_int16(std::string_view text);

} // namespace bench::peer
