/* What the harnesses that start from a loaded scene share (C and C++ alike): level.xml,
 * loaded, or NULL once the reason it did not load is on standard error. */
#include <box2scene.h>

#include <stdio.h>

static b2s_scene* load_level(void) {
    b2s_scene* scene = NULL;
    b2s_error error;
    if (b2s_load_file("level.xml", NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "level.xml:%u:%u: %s\n", error.line, error.column, error.message);
    }
    return scene;
}
