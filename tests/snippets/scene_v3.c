/* The harness of a C snippet that starts from a loaded scene (`scene` is level.xml) and
 * makes a Box2D v3 world, `world`, which the harness destroys. The snippet's own #include
 * names the v3 version. */
#include "snippet_head.h"

#include "level.h"

int main(void) {
    b2s_scene* scene = load_level();
    if (scene == NULL) {
        return 1;
    }
#include "snippet_body.h"
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return 0;
}
