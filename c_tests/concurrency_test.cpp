// Many threads may load and read at once (API convention 3): 8 threads each load 500 scenes,
// the project's files in turn, from disk and from memory, each thread starting at another
// file, and every result must write back to exactly the text the same file gives when
// loaded alone, with the same warnings.
#include <box2scene.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "test_macros.h"
#include "test_scenes.hpp"

static const int kThreads = 8;
static const int kLoadsPerThread = 500;

/// A scene file and what loading it alone gives.
struct Expected {
    std::string path;  // from the project's root
    std::string bytes;
    std::string written; // with its warnings: see fingerprint
};

/// What a scene writes back to, with its warnings appended: equal for equal scenes.
static std::string fingerprint(const b2s_scene* scene) {
    std::string result = written_text(scene);
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    for (uint32_t i = 0; i < view->diagnostic_count; ++i) {
        const b2s_diagnostic& d = view->diagnostics[i];
        result += "\n" + std::to_string(d.code) + ":" + std::to_string(d.line) + ":" +
                  std::to_string(d.column) + ": " + d.message;
    }
    return result;
}

static ScenePtr load(const Expected& file, bool from_disk) {
    if (!from_disk) {
        return load_quietly(file.bytes);
    }
    b2s_scene* scene = nullptr;
    std::string path = std::string(BOX2SCENE_SOURCE_DIR) + "/" + file.path;
    b2s_load_file(path.c_str(), nullptr, &scene, nullptr);
    return ScenePtr(scene);
}

/// Every project scene, loaded alone.
static std::vector<Expected> expected_scenes() {
    std::vector<Expected> files;
    for (const std::string& path : project_scene_files()) {
        Expected file{path, project_file_bytes(path), {}};
        ScenePtr scene = load(file, false);
        if (scene != nullptr) {
            file.written = fingerprint(scene.get());
            files.push_back(file);
        }
    }
    return files;
}

/// One thread's loads: how many gave another scene than the file alone does.
static int loads_differing(const std::vector<Expected>& files, int thread) {
    int differing = 0;
    for (int i = 0; i < kLoadsPerThread; ++i) {
        const Expected& file = files[(thread + i) % files.size()];
        ScenePtr scene = load(file, (thread + i) % 2 == 0);
        if (scene == nullptr || fingerprint(scene.get()) != file.written) {
            ++differing;
        }
    }
    return differing;
}

static int threads_load_what_one_thread_loads() {
    std::vector<Expected> files = expected_scenes();
    ENSURE(files.size() >= 10);
    std::atomic<int> differing{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&files, &differing, t] { differing += loads_differing(files, t); });
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    ENSURE_EQ(differing.load(), 0);
    return 0;
}

int main() {
    int failed = 0;
    failed += RUN_TEST(threads_load_what_one_thread_loads);
    return failed;
}
