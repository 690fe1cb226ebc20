/*
 * What the Box2D v3 adapter's sources (adapter.c and the files it includes) need to know of
 * Box2D v3.1, the one place where the adapter for v3.1 differs from one for another v3
 * (v32.h is v3.2's): its public names and constants. Names starting with b2s3_ are private
 * to the adapter's one translation unit.
 */
#ifndef BOX2SCENE_BOX2D3_V31_H
#define BOX2SCENE_BOX2D3_V31_H

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

#endif /* BOX2SCENE_BOX2D3_V31_H */
