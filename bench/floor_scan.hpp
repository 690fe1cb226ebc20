// A floor under any loader's instruction count: what it costs only to find the markup and
// convert the numbers of a scene, keeping and checking nothing.
#pragma once

#include <cstddef>
#include <cstdint>

namespace bench {

/// What the scan found: the start tags and the numbers, and the sum of the numbers (so
/// that nothing is left out as unused).
struct FloorCount {
    uint64_t start_tags = 0;
    uint64_t numbers = 0;
    double sum = 0;
};

/// Finds every `<` and the `>` after it, eight bytes at a time as box2scene's tokenizer
/// looks for them, and converts every number written between a `>` and the next `<` (white
/// space and commas between them), as box2scene converts the usual float: digits into an
/// integer, then one multiplication or division by an exact power of ten. A number that
/// conversion cannot take ends the text it is in. Nothing else: no names are looked at, no
/// end tag is matched, no character is checked, nothing is kept.
FloorCount floor_scan(const char* text, size_t size);

} // namespace bench
