/*
 * The Box2D v3 half of fidelity_24_vs_v3, compiled as C against v3 on its own: v3's
 * <box2d/box2d.h> and 2.4's cannot share a translation unit.
 */
#ifndef BOX2SCENE_ENGINES_V3_PART_H
#define BOX2SCENE_ENGINES_V3_PART_H

#ifdef __cplusplus
extern "C" {
#endif

/* Loads `xml`, builds it with b2s_box2d3_build_world and steps it `steps` times (1/60 s, 4
 * substeps). Stores each body's x, y and angle in `out` (3 floats per body) and whether a
 * report names it (the body, or a joint on it) in `named`, for up to `capacity` bodies.
 * Returns the scene's body count, or -1 when it does not load. */
int v3_bodies_after(const char* xml, int steps, float* out, unsigned char* named, int capacity);

#ifdef __cplusplus
}
#endif

#endif /* BOX2SCENE_ENGINES_V3_PART_H */
