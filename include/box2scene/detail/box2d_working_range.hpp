// Part of <box2scene/box2d.hpp> (a host includes that header only): values checked against
// box2scene::working_range, and the report for the first one beyond it. Why the bounds are
// what they are: docs/working-range.md.
#ifndef BOX2SCENE_DETAIL_BOX2D_WORKING_RANGE_HPP
#define BOX2SCENE_DETAIL_BOX2D_WORKING_RANGE_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include <cmath>
#include <cstdio>
#include <string>

namespace box2scene {
namespace detail {

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
    check.vector("Gravity", gravity, working_range::acceleration, "m/s^2");
    return check;
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_WORKING_RANGE_HPP
