/*
 * The Box2D v3 adapter's implementation (include/box2scene/box2d3.h is stb-style), compiled
 * into each target that links box2scene::box2d3, against that target's own Box2D v3.
 */
#define B2S_BOX2D3_IMPLEMENTATION
#include <box2scene/box2d3.h>
