// The harness of a C++ snippet that starts from a loaded scene: `scene` is level.xml.
#include "snippet_head.h"

#include "level.h"

int main() {
    b2s_scene* scene = load_level();
    if (scene == nullptr) {
        return 1;
    }
    {
#include "snippet_body.h"
    }
    b2s_scene_free(scene);
    return 0;
}
