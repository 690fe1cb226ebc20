// Part of <box2scene/box2d.hpp> (a host includes that header only): the lookups, the engine
// object built from a named scene record and the record an engine object was built from.
// A Built is indexed like the scene's arrays, so either way is a walk over one array.
#ifndef BOX2SCENE_DETAIL_BOX2D_LOOKUP_HPP
#define BOX2SCENE_DETAIL_BOX2D_LOOKUP_HPP

#ifndef BOX2SCENE_BOX2D_HPP
#error "include <box2scene/box2d.hpp>, not its parts"
#endif

#include <algorithm>
#include <cstdint>
#include <vector>

namespace box2scene {
namespace detail {

/// objects[index] when the scene and the result agree on how many there are, else nullptr.
template <class T>
T* built_at(const std::vector<T*>& objects, uint32_t scene_count, uint32_t index) {
    bool same_scene = objects.size() == scene_count;
    return same_scene && index < scene_count ? objects[index] : nullptr;
}

/// Where `object` stands in `objects`, or B2S_NONE.
template <class T>
uint32_t index_in(const std::vector<T*>& objects, const T* object) {
    if (object == nullptr) {
        return B2S_NONE;
    }
    auto found = std::find(objects.begin(), objects.end(), object);
    return found != objects.end() ? static_cast<uint32_t>(found - objects.begin()) : B2S_NONE;
}

} // namespace detail

inline b2Body* find_body(const Built& built, const b2s_scene* scene, const char* name) {
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    return view != nullptr ? detail::built_at(built.bodies, view->body_count,
                                              b2s_scene_find_body(scene, name))
                           : nullptr;
}

inline b2Fixture* find_fixture(const Built& built, const b2s_scene* scene, const char* name) {
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    uint32_t fixture = b2s_scene_find_fixture(scene, name);
    if (view == nullptr || fixture == B2S_NONE) {
        return nullptr;
    }
    const uint32_t* pool = view->fixture_ids;
    const uint32_t* first = std::find(pool, pool + view->fixture_id_count, fixture);
    return detail::built_at(built.fixtures, view->fixture_id_count,
                            static_cast<uint32_t>(first - pool));
}

inline b2Joint* find_joint(const Built& built, const b2s_scene* scene, const char* name) {
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    return view != nullptr ? detail::built_at(built.joints, view->joint_count,
                                              b2s_scene_find_joint(scene, name))
                           : nullptr;
}

inline uint32_t body_index(const Built& built, const b2Body* body) {
    return detail::index_in(built.bodies, body);
}

inline uint32_t fixture_slot(const Built& built, const b2Fixture* fixture) {
    return detail::index_in(built.fixtures, fixture);
}

inline uint32_t joint_index(const Built& built, const b2Joint* joint) {
    return detail::index_in(built.joints, joint);
}

} // namespace box2scene

#endif // BOX2SCENE_DETAIL_BOX2D_LOOKUP_HPP
