/* load: the smallest complete use of box2scene from C.
 *
 *     load [SCENE]
 *
 * Loads SCENE (default: the bundled showcase), prints what it holds and the load's
 * warnings, and frees it. Exits 1, printing the error and where it is, when the file
 * cannot be loaded. */

#include <box2scene.h>
#include <stdio.h>

static const char *body_kind_name(uint32_t kind) {
    switch (kind) {
    case B2S_BODY_KIND_STATIC: return "static";
    case B2S_BODY_KIND_KINEMATIC: return "kinematic";
    case B2S_BODY_KIND_DYNAMIC: return "dynamic";
    default: return "unknown";
    }
}

int main(int argc, char **argv) {
    const char *path = argc > 1 ? argv[1] : BOX2SCENE_EXAMPLE_SCENE;

    b2s_scene *scene = NULL;
    b2s_error error;
    if (b2s_load_file(path, NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "%s:%u:%u: error[%s]: %s\n", path, error.line, error.column,
                b2s_code_name(error.code), error.message);
        return 1;
    }

    /* Every pointer in the view stays valid until b2s_scene_free. */
    const b2s_scene_view *view = b2s_scene_get_view(scene);
    printf("%s: %u shapes, %u fixtures, %u bodies, %u joints\n", path, view->shape_count,
           view->fixture_count, view->body_count, view->joint_count);
    /* A scene has no default gravity: the host decides when the file gives none. */
    if (view->gravity_given) {
        printf("gravity: (%g, %g)\n", view->gravity.x, view->gravity.y);
    }
    for (uint32_t i = 0; i < view->body_count; ++i) {
        const b2s_body *body = &view->bodies[i];
        printf("body %u: %s (%s)\n", i, body->name ? body->name : "(unnamed)",
               body_kind_name(body->kind));
    }
    for (uint32_t i = 0; i < view->diagnostic_count; ++i) {
        const b2s_diagnostic *warning = &view->diagnostics[i];
        fprintf(stderr, "%s:%u:%u: warning[%s]: %s\n", path, warning->line, warning->column,
                b2s_code_name(warning->code), warning->message);
    }

    b2s_scene_free(scene);
    return 0;
}
