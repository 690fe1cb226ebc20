// Loading scenes in the C++ tests: an owning pointer, loads from text and from files, the
// load error printed when a load that should succeed does not, the project's scene files,
// and a scene written back to text.
#ifndef BOX2SCENE_TEST_SCENES_HPP
#define BOX2SCENE_TEST_SCENES_HPP

#include <box2scene.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

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

/// The scene in `bytes`, or null; nothing printed (for loads that may fail, or that run
/// on many threads at once).
inline ScenePtr load_quietly(const std::string& bytes) {
    b2s_scene* scene = nullptr;
    b2s_load_memory(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), nullptr,
                    &scene, nullptr);
    return ScenePtr(scene);
}

/// Every scene file of the project (`.xml` in its scene folders), as sorted paths from its
/// root.
inline std::vector<std::string> project_scene_files() {
    static const char* const folders[] = {"tests/fixtures/scenes", "tests/fixtures/corpus",
                                          "examples/scenes", "tests/fixtures/adapter",
                                          "tests/fixtures/dialects"};
    std::vector<std::string> files;
    for (const char* folder : folders) {
        std::filesystem::path dir = std::filesystem::path(BOX2SCENE_SOURCE_DIR) / folder;
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            if (entry.path().extension() == ".xml") {
                files.push_back(std::string(folder) + "/" + entry.path().filename().string());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// The bytes of the project file at `relative`, a path from the project's root.
inline std::string project_file_bytes(const std::string& relative) {
    std::ifstream in(std::string(BOX2SCENE_SOURCE_DIR) + "/" + relative, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The scene written back to text (b2s_write_memory) in box2scene's own dialect, which holds
/// every scene (a file's own engine dialect may refuse one), or "" when that fails.
inline std::string written_text(const b2s_scene* scene) {
    char* text = nullptr;
    size_t size = 0;
    b2s_write_options options = b2s_write_options_default();
    options.dialect = B2S_DIALECT_BOX2SCENE;
    if (b2s_write_memory(scene, &options, &text, &size, nullptr) != B2S_CODE_OK) {
        return std::string();
    }
    std::string copy(text, size);
    b2s_text_free(text);
    return copy;
}

#endif // BOX2SCENE_TEST_SCENES_HPP
