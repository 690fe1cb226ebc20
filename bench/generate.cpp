// bench/generate [--warnings] BODIES OUT.xml [SEED]: writes the benchmark scene of BODIES
// bodies (about 1 KB each: 1 000 give about 1 MB), seed 1 by default. The same arguments
// give the same file. With --warnings a tenth of the bodies give a warning and the scene is
// otherwise the same (bench::Warnings::tenth_of_bodies).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "scene_generator.hpp"

static bool parse_count(const char* text, unsigned long long most, unsigned long long& out) {
    char* end = nullptr;
    errno = 0;
    out = std::strtoull(text, &end, 10);
    return errno == 0 && end != text && *end == '\0' && out <= most;
}

int main(int argc, char** argv) {
    const char* program = argv[0];
    bench::Warnings warnings = bench::Warnings::none;
    if (argc > 1 && std::strcmp(argv[1], "--warnings") == 0) {
        warnings = bench::Warnings::tenth_of_bodies;
        --argc;
        ++argv;
    }
    unsigned long long bodies = 0, seed = 1;
    if ((argc != 3 && argc != 4) || !parse_count(argv[1], 1000000, bodies) ||
        (argc == 4 && !parse_count(argv[3], UINT64_MAX, seed))) {
        std::fprintf(stderr,
                     "usage: %s [--warnings] BODIES OUT.xml [SEED]   (BODIES up to 1 000 000: "
                     "about 1 GB)\n",
                     program);
        return 2;
    }
    std::string scene = bench::generate_scene(static_cast<uint32_t>(bodies), seed, warnings);
    std::FILE* file = std::fopen(argv[2], "wb");
    if (file == nullptr || std::fwrite(scene.data(), 1, scene.size(), file) != scene.size() ||
        std::fclose(file) != 0) {
        std::fprintf(stderr, "%s: cannot write %s: %s\n", program, argv[2], std::strerror(errno));
        return 1;
    }
    return 0;
}
