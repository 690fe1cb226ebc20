/*
 * The C API from C (this file is compiled as C, which also proves box2scene.h is valid C):
 * errors with their code, line and column, NULL arguments, the small utilities.
 * Positions are 1-based; columns count characters, not bytes; an error points at the
 * offending element's '<' or at the first non-blank character of the offending value.
 */
#include <box2scene.h>

#include <string.h>

#include "test_macros.h"

/* Loads `xml` expecting failure; `error` receives the details. */
static b2s_code load_failing(const char* xml, b2s_error* error) {
    b2s_scene* scene = (b2s_scene*)1; /* must be overwritten with NULL */
    b2s_code code = b2s_load_memory((const uint8_t*)xml, strlen(xml), NULL, &scene, error);
    if (scene != NULL) {
        fprintf(stderr, "a failed load left a scene pointer behind\n");
        return B2S_CODE_OK;
    }
    return code;
}

static int ensure_error(const char* xml, b2s_code code, uint32_t line, uint32_t column) {
    b2s_error error;
    memset(&error, 0xAB, sizeof error);
    b2s_code returned = load_failing(xml, &error);
    if (returned != code) {
        fprintf(stderr, "got %s (%u:%u: %s)\n", b2s_code_name(returned), error.line,
                error.column, error.message);
    }
    ENSURE_EQ(returned, code);
    ENSURE_EQ(error.code, code);
    ENSURE_EQ(error.line, line);
    ENSURE_EQ(error.column, column);
    ENSURE(memchr(error.message, '\0', sizeof error.message) != NULL);
    ENSURE(error.message[0] != '\0');
    return 0;
}

static int mismatched_tags_are_malformed_xml(void) {
    return ensure_error("<World Version=\"1\">\n"
                        "  <Shapes>\n"
                        "  </Bodies>\n"
                        "</World>\n",
                        B2S_CODE_MALFORMED_XML, 3, 3);
}

static int an_id_past_the_container_is_out_of_range(void) {
    /* Nine fixtures (IDs 0 to 8); the body names 12, after a blank. */
    return ensure_error(
        "<World Version=\"1\">\n"
        "  <Shapes><Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>\n"
        "  <Fixtures>\n"
        "    <Fixture><Shape>0</Shape></Fixture><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>0</Shape></Fixture>\n"
        "    <Fixture><Shape>0</Shape></Fixture><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>0</Shape></Fixture>\n"
        "    <Fixture><Shape>0</Shape></Fixture><Fixture><Shape>0</Shape></Fixture><Fixture><Shape>0</Shape></Fixture>\n"
        "  </Fixtures>\n"
        "  <Bodies>\n"
        "    <Body Type=\"Dynamic\"><Fixtures><ID>8</ID><ID> 12</ID></Fixtures></Body>\n"
        "  </Bodies>\n"
        "  <Joints />\n"
        "</World>\n",
        B2S_CODE_ID_OUT_OF_RANGE, 9, 51);
}

static int a_bad_float_is_located_in_characters(void) {
    /* The name before it holds multi-byte characters: column 59 is byte 63. */
    return ensure_error(
        "<World Version=\"1\">\n"
        "  <Shapes><Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>\n"
        "  <Fixtures>\n"
        "    <Fixture><Name>Gr\xC3\xB6\xC3\x9F" "e \xE2\x88\x85</Name><Shape>0</Shape><Density>abc</Density></Fixture>\n"
        "  </Fixtures>\n"
        "  <Bodies />\n"
        "  <Joints />\n"
        "</World>\n",
        B2S_CODE_INVALID_FLOAT, 4, 59);
}

static int null_arguments_are_reported(void) {
    static const char xml[] = "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints/></World>";
    b2s_scene* scene = NULL;
    b2s_error error;
    ENSURE_EQ(b2s_load_memory((const uint8_t*)xml, sizeof xml - 1, NULL, NULL, &error),
              B2S_CODE_NULL_ARGUMENT);
    ENSURE_EQ(error.code, B2S_CODE_NULL_ARGUMENT);
    ENSURE_EQ(b2s_load_memory(NULL, 10, NULL, &scene, &error), B2S_CODE_NULL_ARGUMENT);
    ENSURE(scene == NULL);
    ENSURE_EQ(b2s_load_file(NULL, NULL, &scene, &error), B2S_CODE_NULL_ARGUMENT);
    ENSURE(scene == NULL);
    ENSURE_EQ(b2s_load_file("scene.xml", NULL, NULL, NULL), B2S_CODE_NULL_ARGUMENT);
    ENSURE_EQ(b2s_fixture_default(NULL), B2S_CODE_NULL_ARGUMENT);
    ENSURE_EQ(b2s_body_default(B2S_BODY_KIND_DYNAMIC, NULL), B2S_CODE_NULL_ARGUMENT);
    ENSURE_EQ(b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, NULL), B2S_CODE_NULL_ARGUMENT);
    ENSURE_EQ(b2s_joint_default(B2S_JOINT_KIND_GEAR, NULL), B2S_CODE_NULL_ARGUMENT);
    ENSURE(b2s_scene_get_view(NULL) == NULL);
    ENSURE_EQ(b2s_scene_find_body(NULL, "ground"), B2S_NONE);
    b2s_scene_free(NULL);
    return 0;
}

static int the_error_struct_is_optional(void) {
    ENSURE_EQ(load_failing("<World Version=\"1\"><Shapes></World>", NULL), B2S_CODE_MALFORMED_XML);
    return 0;
}

static int a_missing_file_is_an_io_error(void) {
    b2s_scene* scene = NULL;
    b2s_error error;
    ENSURE_EQ(b2s_load_file("/nonexistent/box2scene/level.xml", NULL, &scene, &error),
              B2S_CODE_IO);
    ENSURE(scene == NULL);
    ENSURE(strstr(error.message, "level.xml") != NULL);
    return 0;
}

static int a_scene_reads_from_c(void) {
    static const char xml[] =
        "<World Version=\"1\"><Gravity>0 -10</Gravity><Shapes/><Fixtures/>"
        "<Bodies><Body Type=\"Kinematic\"><Name>lift</Name></Body></Bodies><Joints/></World>";
    b2s_scene* scene = NULL;
    b2s_error error;
    b2s_load_options options = b2s_load_options_default();
    options.strict = true;
    ENSURE_EQ(b2s_load_memory((const uint8_t*)xml, sizeof xml - 1, &options, &scene, &error),
              B2S_CODE_OK);
    ENSURE_EQ(error.code, B2S_CODE_OK);
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    ENSURE(view != NULL);
    ENSURE_EQ(view->body_count, 1);
    ENSURE_EQ(view->bodies[0].kind, B2S_BODY_KIND_KINEMATIC);
    ENSURE_STR(view->bodies[0].name, "lift");
    ENSURE(view->gravity_given);
    ENSURE_FLOAT(view->gravity.y, -10.0f);
    ENSURE_EQ(b2s_scene_find_body(scene, "lift"), 0);
    b2s_scene_free(scene);
    return 0;
}

static int names_and_versions(void) {
    ENSURE_STR(b2s_code_name(B2S_CODE_ID_OUT_OF_RANGE), "id-out-of-range");
    ENSURE_STR(b2s_code_name(B2S_CODE_OK), "ok");
    ENSURE_STR(b2s_code_name(9999), "unknown-code");
    ENSURE_STR(b2s_version(), B2S_VERSION_STRING);
    b2s_load_options options = b2s_load_options_default();
    ENSURE_EQ(options.max_depth, 64);
    ENSURE_EQ(options.max_input_bytes, 1ull << 30);
    ENSURE(!options.strict);
    ENSURE(options.threads == 0);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(mismatched_tags_are_malformed_xml);
    failed += RUN_TEST(an_id_past_the_container_is_out_of_range);
    failed += RUN_TEST(a_bad_float_is_located_in_characters);
    failed += RUN_TEST(null_arguments_are_reported);
    failed += RUN_TEST(the_error_struct_is_optional);
    failed += RUN_TEST(a_missing_file_is_an_io_error);
    failed += RUN_TEST(a_scene_reads_from_c);
    failed += RUN_TEST(names_and_versions);
    return failed;
}
