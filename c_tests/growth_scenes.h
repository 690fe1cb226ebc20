/*
 * What the build-time growth tests of both adapters share (linear_build_test.cpp for Box2D
 * 2.4, box2d3_linear_build_test.c for v3): scenes of n objects made with the builder, a
 * process CPU clock (other processes on the machine do not count), and the verdict on two
 * sizes. A build linear in n takes about 16 times as long for 16n objects; one quadratic in
 * n takes 256 times as long. Sizes a factor 16 apart leave room both ways: at 4 000 and
 * 16 000 (linear 4, quadratic 16, the bound 8) a capture of chains on one body, n log n
 * with caches that no longer hold it, measured 5.4 to 8.4 on a busy machine. Valid C11 and
 * C++17.
 */
#ifndef BOX2SCENE_GROWTH_SCENES_H
#define BOX2SCENE_GROWTH_SCENES_H

#include <box2scene.h>

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#define GROWTH_SMALL 2000u
#define GROWTH_LARGE 32000u
/* Runs of each size; the fastest counts (the others met a busy machine). */
#define GROWTH_RUNS 5
/* Between linear (16) and quadratic (256), as far in ratio from each: room for caches, which
 * took the capture of chains on one body to 44 in time where its instructions grow 16 times
 * (callgrind), and for trees of log n depth. */
#define GROWTH_MAX_RATIO 64.0

/* The circles the one-body scene's fixtures cycle through: around (1, 0.5), so that the
 * centre of mass is off the body's origin and moves as fixtures are added. */
#define GROWTH_CIRCLES 16u

static inline float growth_circle_x(uint32_t i) {
    return 1.0f + 2.0f * cosf(0.4f * (float)i);
}

static inline float growth_circle_y(uint32_t i) {
    return 0.5f + 2.0f * sinf(0.4f * (float)i);
}

/* Fixture i's density: three values, so that the sum is no mere count times one mass. */
static inline float growth_density(uint32_t i) {
    return 0.5f + (float)(i % 3u);
}

static inline b2s_scene* growth_finish(b2s_builder* builder) {
    b2s_scene* scene = NULL;
    b2s_error error;
    if (b2s_builder_finish(builder, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "growth scene: %s\n", error.message);
    }
    return scene;
}

/* `b` when every call before it succeeded: NULL once one failed (the builder is freed). */
static inline b2s_builder* growth_check(b2s_builder* builder, b2s_code code) {
    if (code != B2S_CODE_OK) {
        fprintf(stderr, "growth scene: builder refused a record (%s)\n", b2s_code_name(code));
        b2s_builder_free(builder);
        return NULL;
    }
    return builder;
}

/* Adds `body` holding the `count` fixtures of `ids` (NULL when they could not be kept),
 * frees `ids` and finishes the scene; NULL when anything failed. */
static inline b2s_scene* growth_finish_with_body(b2s_builder* b, const b2s_body* body,
                                                 uint32_t* ids, uint32_t count) {
    if (b != NULL && ids != NULL) {
        b = growth_check(b, b2s_builder_add_body(b, body, ids, count, NULL, NULL));
    }
    free(ids);
    if (ids == NULL) {
        b2s_builder_free(b);
        return NULL;
    }
    return b != NULL ? growth_finish(b) : NULL;
}

/* One spinning dynamic body at (3, 4) holding `count` fixtures, each on one of the circles. */
static inline b2s_scene* growth_one_body(uint32_t count) {
    b2s_builder* b = b2s_builder_new();
    for (uint32_t i = 0; i < GROWTH_CIRCLES && b != NULL; ++i) {
        b2s_shape shape;
        b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &shape);
        shape.radius = 0.25f;
        shape.position.x = growth_circle_x(i);
        shape.position.y = growth_circle_y(i);
        b = growth_check(b, b2s_builder_add_shape(b, &shape, NULL, 0, NULL, NULL));
    }
    uint32_t* ids = (uint32_t*)malloc(count * sizeof(uint32_t));
    for (uint32_t i = 0; i < count && b != NULL && ids != NULL; ++i) {
        b2s_fixture fixture;
        b2s_fixture_default(&fixture);
        fixture.shape = i % GROWTH_CIRCLES;
        fixture.density = growth_density(i);
        b = growth_check(b, b2s_builder_add_fixture(b, &fixture, &ids[i], NULL));
    }
    b2s_body body;
    b2s_body_default(B2S_BODY_KIND_DYNAMIC, &body);
    body.position.x = 3.0f;
    body.position.y = 4.0f;
    body.linear_velocity.x = 1.0f;
    body.angular_velocity = 2.0f;
    return growth_finish_with_body(b, &body, ids, count);
}

/* Where the grids of bodies put body i: rows of 128, 1 m apart. */
static inline b2s_vec2 growth_grid_at(uint32_t i) {
    b2s_vec2 at = {(float)(i % 128u), (float)(i / 128u)};
    return at;
}

/* `count` dynamic bodies in a grid, each with its own fixture on one shared box. */
static inline b2s_scene* growth_many_bodies(uint32_t count) {
    b2s_builder* b = b2s_builder_new();
    b2s_shape shape;
    b2s_shape_default(B2S_SHAPE_KIND_POLYGON, &shape);
    const b2s_vec2 box[4] = {{-0.4f, -0.4f}, {0.4f, -0.4f}, {0.4f, 0.4f}, {-0.4f, 0.4f}};
    b = growth_check(b, b2s_builder_add_shape(b, &shape, box, 4, NULL, NULL));
    for (uint32_t i = 0; i < count && b != NULL; ++i) {
        b2s_fixture fixture;
        b2s_fixture_default(&fixture);
        fixture.shape = 0;
        fixture.density = 1.0f;
        uint32_t id = 0;
        b = growth_check(b, b2s_builder_add_fixture(b, &fixture, &id, NULL));
        if (b == NULL) {
            break;
        }
        b2s_body body;
        b2s_body_default(B2S_BODY_KIND_DYNAMIC, &body);
        body.position = growth_grid_at(i);
        b = growth_check(b, b2s_builder_add_body(b, &body, &id, 1, NULL, NULL));
    }
    return b != NULL ? growth_finish(b) : NULL;
}

#define GROWTH_JOINED_BODIES 64u

/* `count` joints (revolute, spring distance and weld in turn) among `bodies` dynamic balls
 * in a grid, joint i from ball i (modulo `bodies`) to its neighbour in the row, each
 * satisfied where the balls start: halfway between them. */
static inline b2s_scene* growth_joints_among(uint32_t count, uint32_t bodies) {
    b2s_builder* b = b2s_builder_new();
    b2s_shape shape;
    b2s_shape_default(B2S_SHAPE_KIND_CIRCLE, &shape);
    shape.radius = 0.5f;
    b = growth_check(b, b2s_builder_add_shape(b, &shape, NULL, 0, NULL, NULL));
    b2s_fixture fixture;
    b2s_fixture_default(&fixture);
    fixture.shape = 0;
    fixture.density = 1.0f;
    uint32_t id = 0;
    if (b != NULL) {
        b = growth_check(b, b2s_builder_add_fixture(b, &fixture, &id, NULL));
    }
    for (uint32_t i = 0; i < bodies && b != NULL; ++i) {
        b2s_body body;
        b2s_body_default(B2S_BODY_KIND_DYNAMIC, &body);
        body.position = growth_grid_at(i);
        b = growth_check(b, b2s_builder_add_body(b, &body, &id, 1, NULL, NULL));
    }
    static const b2s_joint_kind kinds[3] = {B2S_JOINT_KIND_REVOLUTE, B2S_JOINT_KIND_DISTANCE,
                                            B2S_JOINT_KIND_WELD};
    for (uint32_t i = 0; i < count && b != NULL; ++i) {
        b2s_joint joint;
        b2s_joint_default(kinds[i % 3u], &joint);
        uint32_t a = i % bodies;
        bool row_end = a % 128u == 127u || a + 1u == bodies;
        joint.body_a = a;
        joint.body_b = row_end ? a - 1u : a + 1u;
        float side = row_end ? -0.5f : 0.5f; /* the point halfway to the neighbour */
        joint.local_anchor_a.x = side;
        joint.local_anchor_b.x = -side;
        if (joint.kind == B2S_JOINT_KIND_DISTANCE) {
            joint.length = 1.0f;
            joint.frequency_hz = 2.0f;
            joint.damping_ratio = 0.5f;
        }
        b = growth_check(b, b2s_builder_add_joint(b, &joint, NULL, NULL));
    }
    return b != NULL ? growth_finish(b) : NULL;
}

/* `count` joints among 64 balls: the joints grow, the bodies do not. */
static inline b2s_scene* growth_many_joints(uint32_t count) {
    return growth_joints_among(count, GROWTH_JOINED_BODIES);
}

/* `count` joints among `count` balls: joints and bodies grow together, so that work per
 * joint that grows with the bodies shows. */
static inline b2s_scene* growth_joined_bodies(uint32_t count) {
    return growth_joints_among(count, count);
}

/* One static body holding `count` square chain loops in a grid, each its own shape. */
static inline b2s_scene* growth_chains(uint32_t count) {
    b2s_builder* b = b2s_builder_new();
    uint32_t* ids = (uint32_t*)malloc(count * sizeof(uint32_t));
    for (uint32_t i = 0; i < count && b != NULL && ids != NULL; ++i) {
        float x = (float)(i % 128u), y = (float)(i / 128u);
        const b2s_vec2 square[4] = {
            {x - 0.4f, y - 0.4f}, {x + 0.4f, y - 0.4f}, {x + 0.4f, y + 0.4f}, {x - 0.4f, y + 0.4f}};
        b2s_shape shape;
        b2s_shape_default(B2S_SHAPE_KIND_CHAIN, &shape);
        shape.is_loop = true;
        uint32_t index = 0;
        b = growth_check(b, b2s_builder_add_shape(b, &shape, square, 4, &index, NULL));
        if (b == NULL) {
            break;
        }
        b2s_fixture fixture;
        b2s_fixture_default(&fixture);
        fixture.shape = index;
        b = growth_check(b, b2s_builder_add_fixture(b, &fixture, &ids[i], NULL));
    }
    b2s_body body;
    b2s_body_default(B2S_BODY_KIND_STATIC, &body);
    return growth_finish_with_body(b, &body, ids, count);
}

/* The growth tests time work, not the system's pages. glibc serves a block above its mmap
 * threshold with fresh pages from the system and gives them back when it is freed, so each
 * build of the larger size (whose plan alone holds megabytes) pays for first touching them
 * where the smaller one reuses heap it already has: a cost per byte, but one that only the
 * larger size pays. Every block from the heap, and the heap kept, the two sizes compare. */
static inline void growth_keep_memory_in_the_heap(void) {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

/* Seconds of this process's CPU time. */
static inline double growth_clock(void) {
    return (double)clock() / (double)CLOCKS_PER_SEC;
}

/* Prints the two fastest times and their ratio; whether the ratio shows a linear build. */
static inline bool growth_linear(const char* what, double small, double large) {
    double ratio = large / small;
    const double linear = (double)GROWTH_LARGE / GROWTH_SMALL;
    printf("%s: %u in %.4f s, %u in %.4f s: %.2f times as long (linear %.0f, quadratic %.0f)\n",
           what, GROWTH_SMALL, small, GROWTH_LARGE, large, ratio, linear, linear * linear);
    return ratio < GROWTH_MAX_RATIO;
}

#endif /* BOX2SCENE_GROWTH_SCENES_H */
