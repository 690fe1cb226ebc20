// The harness of a C++ snippet that starts from a loaded scene: `scene` is level.xml.
#include "snippet_head.h"

#include <box2scene.h>

#include <cstdio>

int main() {
    b2s_scene* scene = nullptr;
    b2s_error error;
    if (b2s_load_file("level.xml", nullptr, &scene, &error) != B2S_CODE_OK) {
        std::fprintf(stderr, "level.xml:%u:%u: %s\n", error.line, error.column, error.message);
        return 1;
    }
    {
#include "snippet_body.h"
    }
    b2s_scene_free(scene);
    return 0;
}
