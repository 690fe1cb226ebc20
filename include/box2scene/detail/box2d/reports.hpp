// Part of <box2scene/box2d.hpp> (a host includes that header only): the reports of a build
// or a capture and the checks of the working range they come from; what the build and the
// capture share: conversions, floats for reports, and Box2D 2.4.1's own mass arithmetic,
// repeated operation for operation so that the adapter's predictions agree with it.
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

/// Whether b2Body::ResetMassData, for `created`, moves an inertia to the centre of mass,
/// and then asserts that some is left: the summed inertia is positive.
inline bool inertia_centred(const std::vector<FixtureMass>& created, bool fixed_rotation) {
    float sum = 0.0f;
    for (size_t i = created.size(); i-- > 0;) {
        if (created[i].density != 0.0f) {
            sum += created[i].mass.I;
        }
    }
    return sum > 0.0f && !fixed_rotation;
}

/// What b2Body::SetMassData(&m) leaves in a dynamic body (a zero mass becomes 1), with the
/// inertia about the centre of mass.
inline b2MassData set_mass(const b2MassData& m, bool fixed_rotation) {
    b2MassData body{m.mass > 0.0f ? m.mass : 1.0f, m.center, 0.0f};
    if (m.I > 0.0f && !fixed_rotation) {
        body.I = m.I - body.mass * b2Dot(m.center, m.center);
    }
    return body;
}

/// Whether b2Body::SetMassData(&m) would derive a positive inertia about the centre of mass
/// where it uses one: Box2D asserts that it does.
inline bool central_inertia_positive(const b2MassData& m, bool fixed_rotation) {
    bool inertia_used = m.I > 0.0f && !fixed_rotation;
    return !inertia_used || set_mass(m, fixed_rotation).I > 0.0f;
}

/// A bound for a report: as short as it reads.
inline std::string rounded(float v) {
    char text[16];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return text;
}

/// The first value of one object found beyond the working range: what its report says.
class RangeCheck {
public:
    bool passed() const { return problem_.empty(); }
    const std::string& problem() const { return problem_; }

    void magnitude(const std::string& field, float value, float bound, const char* unit) {
        if (passed() && !(std::fabs(value) <= bound)) {
            beyond(field + " " + decimal(value), "within +-" + rounded(bound) + " " + unit);
        }
    }
    void vector(const std::string& field, b2s_vec2 v, float bound, const char* unit) {
        if (passed() && !(std::fabs(v.x) <= bound && std::fabs(v.y) <= bound)) {
            beyond(field + " (" + decimal(v.x) + ", " + decimal(v.y) + ")",
                   "each component within +-" + rounded(bound) + " " + unit);
        }
    }
    void within(const std::string& field, float value, float low, float high,
                const char* unit) {
        if (passed() && !(low <= value && value <= high)) {
            beyond(field + " " + decimal(value),
                   "within [" + rounded(low) + ", " + rounded(high) + "] " + unit);
        }
    }
    void at_least(const std::string& field, float value, float bound, const char* unit) {
        if (passed() && !(value >= bound)) {
            beyond(field + " " + decimal(value), "at least " + rounded(bound) + " " + unit);
        }
    }
    /// 0, or within [low, high]: a derived quantity such as a body's mass.
    void zero_or_within(const std::string& field, float value, float low, float high,
                        const char* unit) {
        if (passed() && value != 0.0f && !(low <= value && value <= high)) {
            beyond(field + " " + decimal(value) + " " + unit,
                   "0 or within [" + rounded(low) + ", " + rounded(high) + "] " + unit);
        }
    }
    /// What Box2D 2.4 asserts against, whatever the bounds.
    void fail(const std::string& what) {
        if (passed()) {
            problem_ = what;
        }
    }

private:
    void beyond(const std::string& value, const std::string& range) {
        problem_ = value + " lies beyond Box2D 2.4's working range (" + range + ")";
    }

    std::string problem_;
};

inline RangeCheck gravity_check(b2s_vec2 gravity) {
    RangeCheck check;
    check.vector("Gravity", gravity, working_range().max_acceleration, "m/s^2");
    return check;
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP
