/* The harness of a C snippet that starts from a loaded scene (`scene` is level.xml) and
 * makes a Box2D v3 world, `world`, which the harness destroys. The snippet's own #include
 * names the v3 version. */
#include "snippet_head.h"

#include <box2scene.h>

#include <stdio.h>

int main(void) {
    b2s_scene* scene = NULL;
    b2s_error error;
    if (b2s_load_file("level.xml", NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "level.xml:%u:%u: %s\n", error.line, error.column, error.message);
        return 1;
    }
#include "snippet_body.h"
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return 0;
}
