/*
 * What the tests of every Box2D v3 adapter share: loading scenes (from text, from the
 * project's files), building them into a new v3 world, stepping, looking reports up, and
 * every scene file of the project. The includer first includes its adapter's header and
 * defines V3_ADAPTER(name) as that adapter's public name and v3_position(body) as a body's
 * position as a b2Vec2; box2d32_support.h does that for the v3.2 adapter.
 */
#ifndef BOX2SCENE_V3_SUPPORT_H
#define BOX2SCENE_V3_SUPPORT_H

#ifndef V3_ADAPTER
#error "define V3_ADAPTER(name) before including v3_support.h"
#endif

typedef V3_ADAPTER(built) v3_built;
typedef V3_ADAPTER(reports) v3_reports;
typedef V3_ADAPTER(report) v3_report;

#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include "test_macros.h"

#define TIME_STEP (1.0f / 60.0f)
#define SUB_STEPS 4

/* The scene in `xml`, or NULL (and the error on stderr). */
static inline b2s_scene* load_text(const char* xml) {
    b2s_scene* scene = NULL;
    b2s_error error;
    b2s_code code = b2s_load_memory((const uint8_t*)xml, strlen(xml), NULL, &scene, &error);
    if (code != B2S_CODE_OK) {
        fprintf(stderr, "inline scene: %u:%u: %s: %s\n", error.line, error.column,
                b2s_code_name(code), error.message);
    }
    return scene;
}

/* The scene in the file at `path`, or NULL (and the error on stderr). */
static inline b2s_scene* load_path(const char* path) {
    b2s_scene* scene = NULL;
    b2s_error error;
    b2s_code code = b2s_load_file(path, NULL, &scene, &error);
    if (code != B2S_CODE_OK) {
        fprintf(stderr, "%s: %u:%u: %s: %s\n", path, error.line, error.column,
                b2s_code_name(code), error.message);
    }
    return scene;
}

/* A v3 world made from the scene's world def, and the scene built into it. */
typedef struct v3_world {
    b2WorldId id;
    v3_built* built;
} v3_world;

static inline v3_world build_v3(const b2s_scene* scene) {
    v3_world world;
    b2WorldDef def = V3_ADAPTER(world_def)(scene, (b2Vec2){0.0f, -10.0f});
    world.id = b2CreateWorld(&def);
    world.built = V3_ADAPTER(build_world)(scene, world.id);
    return world;
}

static inline void free_v3(v3_world* world) {
    V3_ADAPTER(built_free)(world->built);
    b2DestroyWorld(world->id);
}

static inline void step_v3(const v3_world* world, int steps) {
    for (int i = 0; i < steps; ++i) {
        b2World_Step(world->id, TIME_STEP, SUB_STEPS);
    }
}

/* How many reports have `code` (and, when `object` is not NULL, that object and index). */
static inline uint32_t count_reports(const v3_reports* reports, b2s_code code,
                                     const char* object, uint32_t index) {
    uint32_t found = 0;
    for (uint32_t i = 0; i < reports->count; ++i) {
        const v3_report* r = &reports->items[i];
        if (r->code == code &&
            (object == NULL || (strcmp(r->object, object) == 0 && r->index == index))) {
            found += 1;
        }
    }
    return found;
}

static inline void print_reports(const v3_reports* reports) {
    for (uint32_t i = 0; i < reports->count; ++i) {
        const v3_report* r = &reports->items[i];
        fprintf(stderr, "  %s %s %u: %s\n", b2s_code_name(r->code), r->object, r->index,
                r->message);
    }
}

static inline bool finite_vec(b2Vec2 v) {
    return isfinite(v.x) && isfinite(v.y);
}

/* Whether every created body's position, rotation and velocities are finite (the first that
 * is not is named on stderr). */
static inline bool bodies_finite(const v3_world* world) {
    for (uint32_t i = 0; i < world->built->body_count; ++i) {
        b2BodyId body = world->built->bodies[i];
        if (B2_IS_NULL(body)) {
            continue;
        }
        b2Rot q = b2Body_GetRotation(body);
        if (!finite_vec(v3_position(body)) || !finite_vec(b2Body_GetLinearVelocity(body)) ||
            !isfinite(q.c) || !isfinite(q.s) || !isfinite(b2Body_GetAngularVelocity(body))) {
            fprintf(stderr, "body %u is not finite\n", (unsigned)i);
            return false;
        }
    }
    return true;
}

/* Every scene file of the project and of the editor's corpus, as paths; NULL-terminated,
 * freed with free_paths. */
static inline char** scene_files(void) {
    static const char* const folders[] = {"tests/fixtures/scenes", "tests/fixtures/corpus",
                                          "examples/scenes", "tests/fixtures/adapter",
                                          "tests/fixtures/dialects"};
    size_t count = 0, capacity = 64;
    char** paths = (char**)calloc(capacity + 1, sizeof(char*));
    for (size_t f = 0; f < sizeof folders / sizeof folders[0]; ++f) {
        char folder[1024];
        snprintf(folder, sizeof folder, "%s/%s", BOX2SCENE_SOURCE_DIR, folders[f]);
        DIR* dir = opendir(folder);
        if (dir == NULL) {
            continue;
        }
        for (struct dirent* entry; (entry = readdir(dir)) != NULL;) {
            size_t length = strlen(entry->d_name);
            if (length < 4 || strcmp(entry->d_name + length - 4, ".xml") != 0) {
                continue;
            }
            if (count == capacity) {
                capacity *= 2;
                paths = (char**)realloc(paths, (capacity + 1) * sizeof(char*));
            }
            size_t size = strlen(folder) + length + 2;
            paths[count] = (char*)malloc(size);
            snprintf(paths[count], size, "%s/%s", folder, entry->d_name);
            count += 1;
        }
        closedir(dir);
    }
    paths[count] = NULL;
    return paths;
}

static inline void free_paths(char** paths) {
    for (char** p = paths; *p != NULL; ++p) {
        free(*p);
    }
    free(paths);
}

/* A check of one scene file: 0 when it passes. */
typedef int scene_check(const char* path, const b2s_scene* scene, void* context);

/* Runs `check` on every scene file of the project that loads with default options (some are
 * refused on purpose); returns how many failed, and stores how many loaded in `*loaded`. */
static inline int for_each_scene(scene_check* check, void* context, int* loaded) {
    char** paths = scene_files();
    int failed = 0;
    *loaded = 0;
    for (char** path = paths; *path != NULL; ++path) {
        b2s_scene* scene = NULL;
        if (b2s_load_file(*path, NULL, &scene, NULL) != B2S_CODE_OK) {
            continue;
        }
        failed += check(*path, scene, context);
        *loaded += 1;
        b2s_scene_free(scene);
    }
    free_paths(paths);
    return failed;
}

/* build_v3 at a placement. */
static inline v3_world build_v3_at(const b2s_scene* scene, b2Transform placement) {
    v3_world world;
    b2WorldDef def = V3_ADAPTER(world_def)(scene, (b2Vec2){0.0f, -10.0f});
    world.id = b2CreateWorld(&def);
    world.built = V3_ADAPTER(build_world_at)(scene, world.id, placement);
    return world;
}

#endif /* BOX2SCENE_V3_SUPPORT_H */
