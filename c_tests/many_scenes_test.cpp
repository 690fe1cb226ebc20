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
#include <string>
#include <vector>

#include "test_macros.h"
#include "test_scenes.hpp"
#include "test_worlds.hpp"

static const int kScenes = 1000;

/// A scene file's bytes and what its first load gave.
struct SceneFile {
    std::string path; // from the project's root
    std::string bytes;
    std::string written; // b2s_write_memory of the first load
};

static std::vector<SceneFile> project_scenes() {
    std::vector<SceneFile> files;
    for (const std::string& path : project_scene_files()) {
        files.push_back(SceneFile{path, project_file_bytes(path), {}});
    }
    return files;
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
        ScenePtr first = load_quietly(file.bytes);
        ENSURE(first != nullptr);
        file.written = written_text(first.get());
        ENSURE(!file.written.empty());
    }
    for (int i = 0; i < kScenes; ++i) {
        const SceneFile& file = files[i % files.size()];
        bool from_disk = i % 2 == 0;
        ScenePtr scene =
            from_disk ? load_project_file(file.path.c_str()) : load_quietly(file.bytes);
        ENSURE(scene != nullptr);
        if (written_text(scene.get()) != file.written) {
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
