// Part of <box2scene/box2d.hpp> (a host includes that header only): what the build and the
// capture share: the conversions between Box2D's vectors and the library's (every check,
// prediction and inversion is the library's: its plan and its capture).
#ifndef BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP
#define BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

namespace box2scene {
namespace detail {

inline b2Vec2 to_b2(b2s_vec2 v) {
    return b2Vec2(v.x, v.y);
}

inline b2s_vec2 to_b2s(b2Vec2 v) {
    return b2s_vec2{v.x, v.y};
}

} // namespace detail
} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_REPORTS_HPP
