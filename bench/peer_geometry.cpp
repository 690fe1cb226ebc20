#include "peer_geometry.hpp"

#include <cfloat>

namespace bench::peer {
namespace {

constexpr float kLinearSlop = 0.005f; // Box2D's b2_linearSlop (m)
constexpr uint32_t kMaxVertices = 8;  // b2_maxPolygonVertices

b2s_vec2 sub(b2s_vec2 a, b2s_vec2 b) { return b2s_vec2{a.x - b.x, a.y - b.y}; }
float cross(b2s_vec2 a, b2s_vec2 b) { return a.x * b.y - a.y * b.x; }
float length_squared(b2s_vec2 a) { return a.x * a.x + a.y * a.y; }

/// The vertices without those closer than half the linear slop to an earlier one.
uint32_t merge_close_points(const b2s_vec2* vertices, uint32_t count, b2s_vec2* kept) {
    const float weld = 0.5f * kLinearSlop;
    uint32_t n = 0;
    for (uint32_t i = 0; i < count; ++i) {
        bool far = true;
        for (uint32_t k = 0; k < n && far; ++k) {
            far = length_squared(sub(vertices[i], kept[k])) >= weld * weld;
        }
        if (far) {
            kept[n++] = vertices[i];
        }
    }
    return n;
}

/// Box2D 2.4.1's gift wrapping from the rightmost (then lowest) point, collinear points
/// dropped: the hull's indices into `points`, counter-clockwise.
uint32_t convex_hull(const b2s_vec2* points, uint32_t count, uint32_t* hull) {
    uint32_t rightmost = 0;
    for (uint32_t i = 1; i < count; ++i) {
        b2s_vec2 p = points[i], best = points[rightmost];
        if (p.x > best.x || (p.x == best.x && p.y < best.y)) {
            rightmost = i;
        }
    }
    uint32_t n = 0, current = rightmost;
    while (true) {
        hull[n++] = current;
        uint32_t next = 0;
        for (uint32_t j = 1; j < count; ++j) {
            if (next == current) {
                next = j;
                continue;
            }
            b2s_vec2 r = sub(points[next], points[current]);
            b2s_vec2 v = sub(points[j], points[current]);
            float c = cross(r, v);
            if (c < 0.0f || (c == 0.0f && length_squared(v) > length_squared(r))) {
                next = j;
            }
        }
        current = next;
        if (current == rightmost || n > count) {
            return n;
        }
    }
}

float hull_area(const b2s_vec2* points, const uint32_t* hull, uint32_t n) {
    b2s_vec2 origin = points[hull[0]];
    float twice = 0.0f;
    for (uint32_t i = 1; i + 1 < n; ++i) {
        twice += cross(sub(points[hull[i]], origin), sub(points[hull[i + 1]], origin));
    }
    return 0.5f * twice;
}

} // namespace

const char* degenerate_polygon(const b2s_vec2* vertices, uint32_t count) {
    if (count == 2) {
        bool short_segment =
            length_squared(sub(vertices[1], vertices[0])) < kLinearSlop * kLinearSlop;
        return short_segment ? "the two points of this segment polygon are closer than "
                               "Box2D's linear slop"
                             : nullptr;
    }
    b2s_vec2 merged[kMaxVertices];
    uint32_t hull[kMaxVertices + 1];
    uint32_t kept = merge_close_points(vertices, count, merged);
    uint32_t n = convex_hull(merged, kept, hull);
    if (n < 3 || hull_area(merged, hull, n) <= FLT_EPSILON) {
        return "the polygon's points are collinear or (nearly) coincide: it has no area";
    }
    return nullptr;
}

} // namespace bench::peer
