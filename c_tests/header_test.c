/*
 * box2scene.h as a host sees it: compiled as pedantic C99 and, through header_test.cpp, as
 * pedantic C++17, with warnings as errors, using every macro the header defines and the kind
 * enumerations as the parameter types they are.
 */
#include <box2scene.h>
#include <box2scene.h> /* twice: the include guard holds */

#include <stdlib.h>

#include "test_macros.h"
/* Every macro and enumeration constant of box2scene.h, listed from the header at build time. */
#include "header_names.h"

#ifndef BOX2SCENE_H
#error "box2scene.h does not define its include guard"
#endif

/* The version macros are plain integers, usable by the preprocessor. */
#if B2S_VERSION_MAJOR < 0 || B2S_VERSION_MINOR < 0 || B2S_VERSION_PATCH < 0
#error "box2scene.h has a negative version number"
#endif

static int load(const char* text, b2s_scene** scene, b2s_error* error) {
    return (int)b2s_load_memory((const uint8_t*)text, strlen(text), NULL, scene, error);
}

static int version_macros_name_the_library(void) {
    char joined[64];
    snprintf(joined, sizeof joined, "%d.%d.%d", B2S_VERSION_MAJOR, B2S_VERSION_MINOR,
             B2S_VERSION_PATCH);
    ENSURE_STR(B2S_VERSION_STRING, joined);
    ENSURE_STR(b2s_version(), B2S_VERSION_STRING);
    return 0;
}

/* A message longer than the buffer (it quotes 600 digits) is cut to fit, NUL included. */
static int error_message_size_bounds_the_message(void) {
    enum { DIGITS = 600 };
    static const char head[] = "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>";
    static const char tail[] = "x</Radius></Shape></Shapes></World>";
    char text[sizeof head + DIGITS + sizeof tail];
    b2s_scene* scene = NULL;
    b2s_error error;
    ENSURE_EQ(sizeof error.message, B2S_ERROR_MESSAGE_SIZE);
    memcpy(text, head, sizeof head - 1);
    memset(text + sizeof head - 1, '1', DIGITS);
    memcpy(text + sizeof head - 1 + DIGITS, tail, sizeof tail);
    ENSURE_EQ(load(text, &scene, &error), B2S_CODE_INVALID_FLOAT);
    ENSURE(scene == NULL);
    ENSURE_EQ(strlen(error.message), B2S_ERROR_MESSAGE_SIZE - 1);
    return 0;
}

static int none_marks_what_is_absent(void) {
    b2s_scene* scene = NULL;
    b2s_error error;
    const b2s_scene_view* view;
    ENSURE_EQ(load("<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>1</Radius>"
                   "<Position>0 0</Position></Shape></Shapes><Fixtures><Fixture><Shape>0"
                   "</Shape></Fixture></Fixtures><Bodies><Body Type=\"Static\"><Name>Ground"
                   "</Name></Body></Bodies><Joints/></World>",
                   &scene, &error),
              B2S_CODE_OK);
    view = b2s_scene_get_view(scene);
    ENSURE_EQ(view->fixture_count, 1);
    ENSURE_EQ(view->fixtures[0].user_data, B2S_NONE);
    ENSURE_EQ(b2s_scene_find_body(scene, "Ground"), 0);
    ENSURE_EQ(b2s_scene_find_body(scene, "Sky"), B2S_NONE);
    b2s_scene_free(scene);
    return 0;
}

/* One unknown element per warning: B2S_MAX_WARNINGS are kept, then one counts the rest. */
static int max_warnings_caps_the_diagnostics(void) {
    enum { UNKNOWN = B2S_MAX_WARNINGS + 500 };
    static const char head[] = "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints/>";
    static const char item[] = "<x/>";
    static const char tail[] = "</World>";
    size_t size = sizeof head + UNKNOWN * (sizeof item - 1) + sizeof tail;
    char* text = (char*)malloc(size);
    char* at = text;
    b2s_scene* scene = NULL;
    b2s_error error;
    const b2s_scene_view* view;
    int i;
    ENSURE(text != NULL);
    memcpy(at, head, sizeof head - 1);
    at += sizeof head - 1;
    for (i = 0; i < UNKNOWN; ++i, at += sizeof item - 1) memcpy(at, item, sizeof item - 1);
    memcpy(at, tail, sizeof tail);
    i = load(text, &scene, &error);
    free(text);
    ENSURE_EQ(i, B2S_CODE_OK);
    view = b2s_scene_get_view(scene);
    ENSURE_EQ(view->diagnostic_count, B2S_MAX_WARNINGS + 1);
    ENSURE_EQ(view->diagnostics[0].code, B2S_CODE_UNKNOWN_ELEMENT);
    ENSURE_EQ(view->diagnostics[B2S_MAX_WARNINGS].code, B2S_CODE_WARNINGS_TRUNCATED);
    b2s_scene_free(scene);
    return 0;
}

/* The defaults take their kind as the enumeration's type; any other number is refused. */
static int kinds_are_typed_parameters(void) {
    b2s_shape_kind circle = B2S_SHAPE_KIND_CIRCLE;
    b2s_body_kind dynamic = B2S_BODY_KIND_DYNAMIC;
    b2s_joint_kind wheel = B2S_JOINT_KIND_WHEEL;
    b2s_shape shape;
    b2s_body body;
    b2s_joint joint;
    ENSURE_EQ(b2s_shape_default(circle, &shape), B2S_CODE_OK);
    ENSURE_EQ(shape.kind, B2S_SHAPE_KIND_CIRCLE);
    ENSURE_EQ(b2s_body_default(dynamic, &body), B2S_CODE_OK);
    ENSURE_EQ(body.kind, B2S_BODY_KIND_DYNAMIC);
    ENSURE_EQ(b2s_joint_default(wheel, &joint), B2S_CODE_OK);
    ENSURE_FLOAT(joint.frequency_hz, 2.0f);
    ENSURE_EQ(b2s_shape_default((b2s_shape_kind)4, &shape), B2S_CODE_INVALID_ARGUMENT);
    ENSURE_EQ(b2s_body_default((b2s_body_kind)3, &body), B2S_CODE_INVALID_ARGUMENT);
    ENSURE_EQ(b2s_joint_default((b2s_joint_kind)12, &joint), B2S_CODE_INVALID_ARGUMENT);
    return 0;
}

/* Whether `value` is a constant of one of the header's enumerations. */
static int is_enumerated(unsigned long long value) {
    const header_constant* c;
    for (c = header_constants; c->name != NULL; ++c) {
        if (c->enumeration != NULL && c->value == value) return 1;
    }
    return 0;
}

/* Every name the header defines compiles where a host uses it (header_names.h), and holds
 * what its kind promises: the constants of one enumeration differ, every code constant has a
 * name, every string macro is one, every brace list holds constants of an enumeration. */
static int every_name_the_header_defines_is_usable(void) {
    const header_constant* c;
    const header_constant* earlier;
    const header_list* list;
    size_t i, enumerated = 0;
    for (c = header_constants; c->name != NULL; ++c) {
        if (c->enumeration == NULL) continue;
        ++enumerated;
        for (earlier = header_constants; earlier != c; ++earlier) {
            int same_enumeration =
                earlier->enumeration != NULL && strcmp(earlier->enumeration, c->enumeration) == 0;
            if (same_enumeration && earlier->value == c->value) {
                fprintf(stderr, "%s and %s are both %llu\n", earlier->name, c->name, c->value);
                return 1;
            }
        }
        if (strcmp(c->enumeration, "b2s_code") == 0 &&
            strcmp(b2s_code_name((uint32_t)c->value), "unknown-code") == 0) {
            fprintf(stderr, "%s (%llu) has no name\n", c->name, c->value);
            return 1;
        }
    }
    /* The kinds, the severities, the dialects and the codes: the generator found them. */
    ENSURE(enumerated >= 4 + 3 + 12 + 2 + 5 + 60);
    for (i = 0; header_strings[i][0] != NULL; ++i) ENSURE(strlen(header_strings[i][1]) > 0);
    for (list = header_lists; list->name != NULL; ++list) {
        for (i = 0; i < list->count; ++i) {
            if (!is_enumerated(list->values[i])) {
                fprintf(stderr, "%s holds %llu, no constant\n", list->name, list->values[i]);
                return 1;
            }
        }
    }
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(version_macros_name_the_library);
    failed += RUN_TEST(error_message_size_bounds_the_message);
    failed += RUN_TEST(none_marks_what_is_absent);
    failed += RUN_TEST(max_warnings_caps_the_diagnostics);
    failed += RUN_TEST(kinds_are_typed_parameters);
    failed += RUN_TEST(every_name_the_header_defines_is_usable);
    return failed;
}
