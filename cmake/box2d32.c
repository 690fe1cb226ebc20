/*
 * The Box2D v3.2 adapter's implementation (include/box2scene/box2d32.h and the sources of
 * include/box2scene/detail/box2d3/), compiled into each target that links
 * box2scene::box2d32, against that target's own Box2D v3.2.
 */
#define B2S_BOX2D32_IMPLEMENTATION
#include <box2scene/box2d32.h>
