// The peers' polygon check, box2scene's src/validate.rs rule: what Box2D 2.4.1's
// b2PolygonShape::Set would silently replace with a 1x1 box is an error.
#pragma once

#include <box2scene.h>

#include <cstdint>

namespace bench::peer {

/// Why a polygon of `count` vertices (2 to 8) is degenerate, or nullptr when it is not: a
/// segment shorter than the linear slop, or points that (once those closer than half the
/// slop are merged) leave a hull of fewer than 3 points or no area.
const char* degenerate_polygon(const b2s_vec2* vertices, uint32_t count);

} // namespace bench::peer
