/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.1, the one place where the adapter for v3.1 differs from one for another v3
 * (v32.h is v3.2's): its public names and constants. Names starting with b2s3_ are private
 * to the adapter's one translation unit.
 */
#ifndef BOX2SCENE_BOX2D3_V31_H
#define BOX2SCENE_BOX2D3_V31_H

#include <stdlib.h>

/* The public names: b2s_box2d3_NAME, B2S_BOX2D3_LIMIT (box2scene/box2d3.h keeps v3.1's names
 * as they were before v3.2 was served). */
#define B2S3_API(name) b2s_box2d3_##name
#define B2S3_LIMIT(name) B2S_BOX2D3_##name
/* The engine, as reports name it. */
#define B2S3_ENGINE "Box2D v3"

typedef b2s_box2d3_report b2s3_report_t;
typedef b2s_box2d3_reports b2s3_reports_t;
typedef b2s_box2d3_built b2s3_built_t;

/* v3.1's linear slop (B2_LINEAR_SLOP in its private constants.h) at one length unit per
 * metre: v3.1 refuses a segment no longer than it and raises a distance joint's length to
 * it. */
#define B2S3_LINEAR_SLOP 0.005f

/* ---- chains: v3.1's own (b2ChainDef), one b2ChainId per fixture slot */

/* v3.1 asserts that a loop has 4 points or more. */
#define B2S3_MIN_LOOP_POINTS 4

/* What a chain loses of its fixture's shape def: v3.1's chains cannot be sensors. */
static const char* b2s3_chain_loss(const b2ShapeDef* def) {
    return def->isSensor ? "is a sensor, but Box2D v3's chains have no sensor form; it was "
                           "made a solid chain"
                         : NULL;
}

static bool b2s3_allocate_chains(b2s3_built_t* built, uint32_t slots) {
    built->chains = (b2ChainId*)calloc(slots + 1, sizeof(b2ChainId));
    return built->chains != NULL;
}

static void b2s3_free_chains(b2s3_built_t* built) {
    free(built->chains);
}

/* A chain of `n` points ([ghost, vertices..., ghost], or a loop) with the shape def's
 * material, filter and events. Never runs out of memory: v3.1 keeps the chain. */
static bool b2s3_create_chain(b2s3_built_t* built, uint32_t* capacity, uint32_t slot,
                              b2BodyId body, const b2ShapeDef* shape, const b2Vec2* points, int n,
                              bool loop) {
    (void)capacity;
    b2ChainDef def = b2DefaultChainDef();
    def.points = points;
    def.count = n;
    def.isLoop = loop;
    def.materials = &shape->material;
    def.materialCount = 1;
    def.filter = shape->filter;
    def.enableSensorEvents = shape->enableSensorEvents;
    built->chains[slot] = b2CreateChain(body, &def);
    return true;
}

#endif /* BOX2SCENE_BOX2D3_V31_H */
