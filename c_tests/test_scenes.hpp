// Loading scenes in the C++ tests: an owning pointer, loads from text and from files, and
// the load error printed when a load that should succeed does not.
#ifndef BOX2SCENE_TEST_SCENES_HPP
#define BOX2SCENE_TEST_SCENES_HPP

#include <box2scene.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

struct SceneFree {
    void operator()(b2s_scene* scene) const { b2s_scene_free(scene); }
};
using ScenePtr = std::unique_ptr<b2s_scene, SceneFree>;

inline void print_load_error(const char* what, b2s_code code, const b2s_error& error) {
    std::fprintf(stderr, "%s: %u:%u: %s: %s\n", what, error.line, error.column,
                 b2s_code_name(code), error.message);
}

/// The scene in `xml`, or null (and the error on stderr).
inline ScenePtr load_text(const char* xml) {
    b2s_scene* scene = nullptr;
    b2s_error error{};
    b2s_code code = b2s_load_memory(reinterpret_cast<const uint8_t*>(xml), std::strlen(xml),
                                    nullptr, &scene, &error);
    if (code != B2S_CODE_OK) {
        print_load_error("inline scene", code, error);
    }
    return ScenePtr(scene);
}

/// The scene in the file at `relative`, a path from the project's root.
inline ScenePtr load_project_file(const char* relative) {
    std::string path = std::string(BOX2SCENE_SOURCE_DIR) + "/" + relative;
    b2s_scene* scene = nullptr;
    b2s_error error{};
    b2s_code code = b2s_load_file(path.c_str(), nullptr, &scene, &error);
    if (code != B2S_CODE_OK) {
        print_load_error(path.c_str(), code, error);
    }
    return ScenePtr(scene);
}

inline const struct b2s_scene_view& view_of(const ScenePtr& scene) {
    return *b2s_scene_get_view(scene.get());
}

#endif // BOX2SCENE_TEST_SCENES_HPP
