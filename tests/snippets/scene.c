/* The harness of a C snippet that starts from a loaded scene (`scene` is level.xml), with no
 * Box2D; the harness frees the scene. */
#include "snippet_head.h"

#include "level.h"

/* The body's own function, so that its `return 1` leaves it and the harness frees `scene`. */
static int snippet(b2s_scene* scene) {
#include "snippet_body.h"
    return 0;
}

int main(void) {
    b2s_scene* scene = load_level();
    if (scene == NULL) {
        return 1;
    }
    const int status = snippet(scene);
    b2s_scene_free(scene);
    return status;
}
