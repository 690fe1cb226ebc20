// The benchmark's scenes: deterministic Box2Scene files of any size, in every spelling the
// format allows, that box2scene and the pugixml peer both load without a warning.
#pragma once

#include <cstdint>
#include <string>

namespace bench {

/// A Version 2 scene with `bodies` bodies of 1 to 3 fixtures each (fixtures and shapes
/// shared between them), bodies / 4 joints cycling through every joint kind, names on some
/// objects, comments, CDATA and entities: about 1 KB of XML per body. The same arguments
/// give the same bytes on every machine.
std::string generate_scene(uint32_t bodies, uint64_t seed);

} // namespace bench
