// The benchmark's scenes: deterministic Box2Scene files of any size, in every spelling the
// format allows, that box2scene and the peers all load alike, box2scene without a
// warning unless one is asked for.
#pragma once

#include <cstdint>
#include <string>

namespace bench {

/// Which warnings a generated scene gives when box2scene loads it.
enum class Warnings {
    none,
    /// Exactly bodies / 10 bodies give `dynamic-body-zero-density`: some fixtures omit their
    /// density, as the editor's files do, and each warning body is a dynamic one without a
    /// MassData mass that holds such a fixture. Only those `Density` elements differ from the
    /// scene without warnings (about 0.2% fewer bytes); the values read are the same but for
    /// those densities, which are 0.
    tenth_of_bodies,
};

/// A Version 2 scene with `bodies` bodies of 1 to 3 fixtures each (fixtures and shapes
/// shared between them), bodies / 4 joints cycling through every joint kind, names on some
/// objects, comments, CDATA and entities: about 1 KB of XML per body. The same arguments
/// give the same bytes on every machine.
std::string generate_scene(uint32_t bodies, uint64_t seed, Warnings warnings = Warnings::none);

} // namespace bench
