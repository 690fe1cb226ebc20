// Part of <box2scene/box2d.hpp> (a host includes that header only): what the build and the
// capture share: conversions, floats for the capture's reports, and Box2D 2.4.1's own mass
// arithmetic, repeated operation for operation so that the capture's inversions agree with
// it (the build's checks and predictions are the library's plan).
#ifndef BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP
#define BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace box2scene {
namespace detail {

inline b2Vec2 to_b2(b2s_vec2 v) {
    return b2Vec2(v.x, v.y);
}

inline b2s_vec2 to_b2s(b2Vec2 v) {
    return b2s_vec2{v.x, v.y};
}

/// A float for a report: every digit that tells it from its neighbours.
inline std::string decimal(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
    return text;
}

/// A fixture as build_world recreates it: what its body's mass is made of.
struct FixtureMass {
    float density;
    b2MassData mass; ///< of the rebuilt shape at that density
};

/// What b2Body::ResetMassData leaves in a dynamic body holding `created` (its fixture list
/// is newest first), operation for operation as Box2D 2.4.1 does it so that the bits agree:
/// mass, centre, and inertia about the centre in `I`.
inline b2MassData reset_mass(const std::vector<FixtureMass>& created, bool fixed_rotation) {
    b2MassData body{0.0f, b2Vec2_zero, 0.0f};
    for (size_t i = created.size(); i-- > 0;) {
        if (created[i].density == 0.0f) {
            continue;
        }
        const b2MassData& m = created[i].mass;
        body.mass += m.mass;
        body.center += m.mass * m.center;
        body.I += m.I;
    }
    if (body.mass > 0.0f) {
        float inverse = 1.0f / body.mass;
        body.center *= inverse;
    }
    if (body.I > 0.0f && !fixed_rotation) {
        body.I -= body.mass * b2Dot(body.center, body.center);
    } else {
        body.I = 0.0f;
    }
    return body;
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP
