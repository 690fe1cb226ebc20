/* A C host of an installed box2scene: prints the library's version and what a scene holds. */
#include <box2scene.h>
#include <stdio.h>

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s SCENE.xml\n", argv[0]);
        return 2;
    }
    b2s_scene *scene = NULL;
    b2s_error error;
    if (b2s_load_file(argv[1], NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "%s:%u:%u: error[%s]: %s\n", argv[1], error.line, error.column,
                b2s_code_name(error.code), error.message);
        return 1;
    }
    const struct b2s_scene_view *view = b2s_scene_get_view(scene);
    printf("box2scene %s (header %s)\n", b2s_version(), B2S_VERSION_STRING);
    printf("%u shapes, %u fixtures, %u bodies, %u joints, %u diagnostics\n", view->shape_count,
           view->fixture_count, view->body_count, view->joint_count, view->diagnostic_count);
    for (uint32_t i = 0; i < view->body_count; ++i) {
        printf("body %u: %s\n", i, view->bodies[i].name ? view->bodies[i].name : "(unnamed)");
    }
    b2s_scene_free(scene);
    return 0;
}
