// The measurements bench/run makes, one mode per kind of measurement:
//
//   bench_driver time RUNS FILE... box2scene and the two peers, interleaved, in RUNS rounds
//                                  over every FILE: parsing it already in memory (box2scene
//                                  with its default options; the rapidxml peer copying it
//                                  first, as it must), loading it from its path (box2scene
//                                  with its default options, and with threads = 1);
//                                  box2scene writing it back and building its b2World.
//                                  Prints "FILE name value" lines, medians in seconds.
//   bench_driver rss LOADER FILE   loads FILE from its path once, box2scene with its default
//                                  options (a fresh process per measurement), and prints the
//                                  peak RSS in KiB before the load (the process itself) and
//                                  after it.
//   bench_driver once LOADER FILE [THREADS]
//                                  reads FILE into memory and loads it once, for callgrind;
//                                  LOADER `read` only reads, the baseline to subtract, and
//                                  `write` loads and then writes the scene back (callgrind
//                                  counts only b2s_write_memory there), and `path` loads
//                                  FILE with box2scene from its path instead, as
//                                  b2s_load_file reads it. THREADS is box2scene's `threads`
//                                  option, 0 (its choice) by default. LOADER `floor` only
//                                  finds the markup and converts the numbers
//                                  (bench/floor_scan.hpp): a floor under both loaders' counts.
//
// LOADER is box2scene, pugixml or rapidxml (the peers of bench/pugi_loader.hpp and
// bench/rapidxml_loader.hpp).
#include <box2d/box2d.h>
#include <box2scene.h>
#include <box2scene/box2d.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "file_bytes.hpp"
#include "floor_scan.hpp"
#include "pugi_loader.hpp"
#include "rapidxml_loader.hpp"

namespace {

/// Writing is measured in box2scene's own form: the generated scene reads as Farseer 3.3's
/// dialect (Version 2, FilterData before Friction), whose reader cannot hold its comment.
const b2s_write_options kOwnForm = [] {
    b2s_write_options options = b2s_write_options_default();
    options.dialect = B2S_DIALECT_BOX2SCENE;
    return options;
}();

using Clock = std::chrono::steady_clock;

[[noreturn]] void die(const std::string& message) {
    std::fprintf(stderr, "bench_driver: %s\n", message.c_str());
    std::exit(1);
}

template <typename Work>
double seconds(Work work) {
    Clock::time_point start = Clock::now();
    work();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

/// The whole file, or exit.
std::unique_ptr<char[]> file_bytes(const char* path, size_t& size) {
    std::unique_ptr<char[]> bytes = bench::read_file(path, size);
    if (!bytes) {
        die(std::string("cannot read ") + path);
    }
    return bytes;
}

/// A fresh writable copy: the pugixml peer parses in place, so every run needs its own.
std::unique_ptr<char[]> copy_of(const char* bytes, size_t size) {
    std::unique_ptr<char[]> copy(new char[size]);
    std::memcpy(copy.get(), bytes, size);
    return copy;
}

b2s_load_options with_threads(uint32_t threads) {
    b2s_load_options options = b2s_load_options_default();
    options.threads = threads;
    return options;
}

b2s_scene* box2scene_from_memory(const char* bytes, size_t size, uint32_t threads = 0) {
    b2s_scene* scene = nullptr;
    b2s_error error;
    b2s_load_options options = with_threads(threads);
    if (b2s_load_memory(reinterpret_cast<const uint8_t*>(bytes), size, &options, &scene,
                        &error) != B2S_CODE_OK) {
        die(std::string("box2scene: ") + error.message);
    }
    return scene;
}

/// `b2s_load_file` as a host calls it (threads = 0: two threads from 1 MiB), or on one
/// thread, as the peer reads.
b2s_scene* box2scene_from_path(const char* path, uint32_t threads = 0) {
    b2s_scene* scene = nullptr;
    b2s_error error;
    b2s_load_options options = with_threads(threads);
    if (b2s_load_file(path, &options, &scene, &error) != B2S_CODE_OK) {
        die(std::string("box2scene: ") + error.message);
    }
    return scene;
}

/// A peer's load, or exit saying why it failed.
void loaded_or_die(const char* peer, bool loaded, const std::string& error) {
    if (!loaded) {
        die(std::string(peer) + " peer: " + error);
    }
}

/// The pugixml peer parses `bytes` itself, in place.
void pugixml_from_memory(std::unique_ptr<char[]> bytes, size_t size, bench::PeerScene& scene) {
    std::string error;
    loaded_or_die("pugixml", bench::pugi_load(std::move(bytes), size, scene, error), error);
}

/// The rapidxml peer copies `bytes` and parses the copy.
void rapidxml_from_memory(const char* bytes, size_t size, bench::PeerScene& scene) {
    std::string error;
    loaded_or_die("rapidxml", bench::rapidxml_load(bytes, size, scene, error), error);
}

void pugixml_from_path(const char* path, bench::PeerScene& scene) {
    std::string error;
    loaded_or_die("pugixml", bench::pugi_load_file(path, scene, error), error);
}

void rapidxml_from_path(const char* path, bench::PeerScene& scene) {
    std::string error;
    loaded_or_die("rapidxml", bench::rapidxml_load_file(path, scene, error), error);
}

/// What the timing mode collects, one sample per run.
struct Samples {
    std::vector<double> box2scene_parse, pugixml_parse, rapidxml_parse;
    std::vector<double> box2scene_path, box2scene_path1, pugixml_path, rapidxml_path;
    std::vector<double> write, build;
};

/// One file under measurement.
struct Subject {
    const char* path;
    size_t size = 0;
    std::unique_ptr<char[]> bytes;
    b2s_scene* loaded = nullptr; // what writing and building start from
    Samples samples;
};

/// Calls the three in turn, `first` (0, 1 or 2) first and the others after it in a circle.
template <typename A, typename B, typename C>
void in_turn(size_t first, A a, B b, C c) {
    for (size_t turn = 0; turn < 3; ++turn) {
        switch ((first + turn) % 3) {
        case 0: a(); break;
        case 1: b(); break;
        default: c(); break;
        }
    }
}

/// One run of every measurement on `s`. The loaders take turns going first, so that none
/// always meets the caches (and the other processes) another left.
void measure_once(Subject& s) {
    Samples& samples = s.samples;
    auto box2scene_parse = [&] {
        b2s_scene* scene = nullptr;
        samples.box2scene_parse.push_back(
            seconds([&] { scene = box2scene_from_memory(s.bytes.get(), s.size); }));
        b2s_scene_free(scene);
    };
    auto pugixml_parse = [&] {
        std::unique_ptr<char[]> copy = copy_of(s.bytes.get(), s.size);
        bench::PeerScene scene;
        samples.pugixml_parse.push_back(
            seconds([&] { pugixml_from_memory(std::move(copy), s.size, scene); }));
    };
    auto rapidxml_parse = [&] {
        bench::PeerScene scene;
        samples.rapidxml_parse.push_back(
            seconds([&] { rapidxml_from_memory(s.bytes.get(), s.size, scene); }));
    };
    auto box2scene_path = [&] {
        b2s_scene* scene = nullptr;
        samples.box2scene_path.push_back(seconds([&] { scene = box2scene_from_path(s.path); }));
        b2s_scene_free(scene);
        samples.box2scene_path1.push_back(
            seconds([&] { scene = box2scene_from_path(s.path, 1); }));
        b2s_scene_free(scene);
    };
    auto pugixml_path = [&] {
        bench::PeerScene scene;
        samples.pugixml_path.push_back(seconds([&] { pugixml_from_path(s.path, scene); }));
    };
    auto rapidxml_path = [&] {
        bench::PeerScene scene;
        samples.rapidxml_path.push_back(seconds([&] { rapidxml_from_path(s.path, scene); }));
    };
    size_t first = samples.write.size() % 3;
    in_turn(first, box2scene_parse, pugixml_parse, rapidxml_parse);
    in_turn(first, box2scene_path, pugixml_path, rapidxml_path);
    char* text = nullptr;
    samples.write.push_back(seconds([&] {
        if (b2s_write_memory(s.loaded, &kOwnForm, &text, nullptr, nullptr) != B2S_CODE_OK) {
            die("box2scene could not write the scene");
        }
    }));
    b2s_text_free(text);
    b2World world(box2scene::scene_gravity(s.loaded, b2Vec2(0, -10)));
    samples.build.push_back(seconds([&] { box2scene::build_world(s.loaded, world); }));
}

/// Files of a few milliseconds are what other processes disturb most: each round measures
/// those under 10 MB as often as makes 10 MB (at most 10 times).
int repeats(size_t size) {
    size_t times = (10000000 + size - 1) / std::max<size_t>(size, 1);
    return static_cast<int>(std::clamp<size_t>(times, 1, 10));
}

void report(const Subject& s) {
    const char* path = s.path;
    char* text = nullptr;
    size_t written = 0;
    b2s_write_memory(s.loaded, &kOwnForm, &text, &written, nullptr);
    b2s_text_free(text);
    b2World world(box2scene::scene_gravity(s.loaded, b2Vec2(0, -10)));
    box2scene::Built built = box2scene::build_world(s.loaded, world);
    const Samples& m = s.samples;
    std::printf("%s bytes %zu\n", path, s.size);
    std::printf("%s runs %zu\n", path, m.write.size());
    std::printf("%s box2scene.parse %.9f\n", path, median(m.box2scene_parse));
    std::printf("%s pugixml.parse %.9f\n", path, median(m.pugixml_parse));
    std::printf("%s rapidxml.parse %.9f\n", path, median(m.rapidxml_parse));
    std::printf("%s box2scene.path %.9f\n", path, median(m.box2scene_path));
    std::printf("%s box2scene.path1 %.9f\n", path, median(m.box2scene_path1));
    std::printf("%s pugixml.path %.9f\n", path, median(m.pugixml_path));
    std::printf("%s rapidxml.path %.9f\n", path, median(m.rapidxml_path));
    std::printf("%s box2scene.write %.9f\n", path, median(m.write));
    std::printf("%s box2scene.written %zu\n", path, written);
    std::printf("%s box2scene.build %.9f\n", path, median(m.build));
    std::printf("%s box2scene.build_reports %zu\n", path, built.reports.size());
}

int time_loaders(int runs, char** paths, int count) {
    std::vector<Subject> subjects(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        Subject& s = subjects[static_cast<size_t>(i)];
        s.path = paths[i];
        s.bytes = file_bytes(s.path, s.size);
        s.loaded = box2scene_from_memory(s.bytes.get(), s.size);
    }
    for (int round = 0; round < runs; ++round) {
        for (Subject& s : subjects) {
            for (int k = repeats(s.size); k > 0; --k) {
                measure_once(s);
            }
        }
    }
    for (Subject& s : subjects) {
        report(s);
        b2s_scene_free(s.loaded);
    }
    return 0;
}

long peak_rss_kib() {
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss; // KiB on Linux
}

int peak_rss(const std::string& loader, const char* path) {
    long before = peak_rss_kib();
    if (loader == "box2scene") {
        b2s_scene* scene = box2scene_from_path(path);
        std::printf("%ld %ld\n", before, peak_rss_kib());
        b2s_scene_free(scene);
    } else {
        bench::PeerScene scene;
        loader == "pugixml" ? pugixml_from_path(path, scene) : rapidxml_from_path(path, scene);
        std::printf("%ld %ld\n", before, peak_rss_kib());
    }
    return 0;
}

int load_once(const std::string& loader, const char* path, uint32_t threads) {
    if (loader == "path") {
        b2s_scene_free(box2scene_from_path(path, threads));
        return 0;
    }
    size_t size = 0;
    std::unique_ptr<char[]> bytes = file_bytes(path, size);
    if (loader == "box2scene") {
        b2s_scene_free(box2scene_from_memory(bytes.get(), size, threads));
    } else if (loader == "write") {
        b2s_scene* scene = box2scene_from_memory(bytes.get(), size, threads);
        char* text = nullptr;
        size_t written = 0;
        if (b2s_write_memory(scene, &kOwnForm, &text, &written, nullptr) != B2S_CODE_OK) {
            die("box2scene could not write the scene");
        }
        std::printf("%zu\n", written);
        b2s_text_free(text);
        b2s_scene_free(scene);
    } else if (loader == "floor") {
        bench::FloorCount count = bench::floor_scan(bytes.get(), size);
        std::printf("%llu start tags, %llu numbers adding up to %g\n",
                    static_cast<unsigned long long>(count.start_tags),
                    static_cast<unsigned long long>(count.numbers), count.sum);
    } else if (loader == "pugixml") {
        bench::PeerScene scene;
        pugixml_from_memory(std::move(bytes), size, scene);
    } else if (loader == "rapidxml") {
        bench::PeerScene scene;
        rapidxml_from_memory(bytes.get(), size, scene);
    }
    return 0;
}

bool is_loader(const std::string& name, bool or_others) {
    return name == "box2scene" || name == "pugixml" || name == "rapidxml" ||
           (or_others && (name == "read" || name == "write" || name == "path" || name == "floor"));
}

} // namespace

int main(int argc, char** argv) {
    std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "time" && argc >= 4 && std::atoi(argv[2]) > 0) {
        return time_loaders(std::atoi(argv[2]), argv + 3, argc - 3);
    }
    if (mode == "rss" && argc == 4 && is_loader(argv[2], false)) {
        return peak_rss(argv[2], argv[3]);
    }
    if (mode == "once" && (argc == 4 || argc == 5) && is_loader(argv[2], true)) {
        uint32_t threads = argc == 5 ? static_cast<uint32_t>(std::atoi(argv[4])) : 0;
        return load_once(argv[2], argv[3], threads);
    }
    std::fprintf(stderr,
                 "usage: %s time RUNS FILE... | rss box2scene|pugixml|rapidxml FILE | "
                 "once read|box2scene|pugixml|rapidxml|write|path|floor FILE [THREADS]\n",
                 argv[0]);
    return 2;
}
