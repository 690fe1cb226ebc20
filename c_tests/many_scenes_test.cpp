// A thousand scenes loaded and freed, the way a long-running host (an editor, a level server)
// does it: every file of the project in turn, from disk and from memory, each written back
// to text, some built into a world, stepped and captured, and a broken copy of each failing
// to load. Run under AddressSanitizer and valgrind (tools/check-memory), it proves that none
// of these paths leaks or touches memory it does not own; here it also checks that loading
// the same bytes always gives the same scene.
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

static const int kScenes = 1000;
static const char* const kSceneFolders[] = {"tests/scenes", "tests/data/corpus",
                                            "examples/scenes", "c_tests/data"};

/// A scene file's bytes and what its first load gave.
struct SceneFile {
    std::string path; // from the project's root
    std::string bytes;
    std::string written; // b2s_write_memory of the first load
};

static std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

static std::string written(const b2s_scene* scene) {
    char* text = nullptr;
    size_t size = 0;
    if (b2s_write_memory(scene, nullptr, &text, &size, nullptr) != B2S_CODE_OK) {
        return std::string();
    }
    std::string copy(text, size);
    b2s_text_free(text);
    return copy;
}

static std::vector<SceneFile> project_scenes() {
    std::vector<SceneFile> files;
    for (const char* folder : kSceneFolders) {
        std::filesystem::path dir = std::filesystem::path(BOX2SCENE_SOURCE_DIR) / folder;
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            if (entry.path().extension() == ".xml") {
                std::string path = std::string(folder) + "/" + entry.path().filename().string();
                files.push_back(SceneFile{path, read_bytes(entry.path()), {}});
            }
        }
    }
    return files;
}

static ScenePtr load_bytes(const std::string& bytes) {
    b2s_scene* scene = nullptr;
    b2s_load_memory(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), nullptr,
                    &scene, nullptr);
    return ScenePtr(scene);
}

/// The load that must fail: the file cut in half, its root never closed.
static int broken_copy_fails(const SceneFile& file) {
    std::string half = file.bytes.substr(0, file.bytes.size() / 2);
    b2s_scene* scene = nullptr;
    b2s_error error{};
    b2s_code code = b2s_load_memory(reinterpret_cast<const uint8_t*>(half.data()), half.size(),
                                    nullptr, &scene, &error);
    ENSURE(code != B2S_CODE_OK);
    ENSURE(scene == nullptr);
    ENSURE_EQ(error.code, code);
    return 0;
}

/// Builds the scene, steps it and captures the world back: the adapter's and the builder's
/// allocations, and Box2D's, freed with them.
static int builds_steps_and_captures(const b2s_scene* scene) {
    b2World world(box2scene::scene_gravity(scene, b2Vec2(0.0f, -10.0f)));
    box2scene::build_world(scene, world);
    step_for(world, 10);
    std::vector<box2scene::Report> reports;
    ScenePtr captured(box2scene::capture_world(world, reports));
    ENSURE(captured != nullptr);
    return 0;
}

static int a_thousand_scenes_load_and_free() {
    std::vector<SceneFile> files = project_scenes();
    ENSURE(files.size() >= 10);
    for (SceneFile& file : files) {
        ScenePtr first = load_bytes(file.bytes);
        ENSURE(first != nullptr);
        file.written = written(first.get());
        ENSURE(!file.written.empty());
    }
    for (int i = 0; i < kScenes; ++i) {
        const SceneFile& file = files[i % files.size()];
        bool from_disk = i % 2 == 0;
        ScenePtr scene = from_disk ? load_project_file(file.path.c_str()) : load_bytes(file.bytes);
        ENSURE(scene != nullptr);
        if (written(scene.get()) != file.written) {
            std::fprintf(stderr, "load %d of %s gave another scene\n", i, file.path.c_str());
            return 1;
        }
        if (i % 25 == 0) {
            ENSURE(builds_steps_and_captures(scene.get()) == 0);
        }
        ENSURE(broken_copy_fails(file) == 0);
    }
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(a_thousand_scenes_load_and_free);
    return failed;
}
