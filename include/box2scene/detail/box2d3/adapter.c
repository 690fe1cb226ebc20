/*
 * The Box2D v3 adapter: one translation unit per Box2D version, so that every function but
 * the public ones stays static. Each version's header includes it after the version's own
 * (v31.h, v32.h), which holds all that differs: box2scene/box2d3.h where the host defines
 * B2S_BOX2D3_IMPLEMENTATION, box2scene/box2d32.h where it defines
 * B2S_BOX2D32_IMPLEMENTATION; CMake's box2scene::box2d3 and box2scene::box2d32 targets
 * compile it (cmake/box2d3.c, cmake/box2d32.c). It is cut as Box2D cuts its own sources, so
 * that a fix in one concept is found by file name:
 *   hooks.h     what a version's header defines (v31.h, v32.h), declared once
 *   reports.c   the reports, and the checks of the working range they come from
 *   world.c     the world def, the placement, one build from start to end
 *   shapes.c    a scene shape as v3 geometry, and the shapes a fixture makes of it
 *   bodies.c    a body, and its mass
 *   joints.c    the joints
 *   capture.c   a live world back into a scene
 *   lookup.c    the engine object of a named record, and the record of an engine object
 */
#ifndef BOX2SCENE_BOX2D3_ADAPTER_C
#define BOX2SCENE_BOX2D3_ADAPTER_C

#ifndef B2S3_API
#error "compile the Box2D v3 adapter through its version's header (box2scene/box2d3.h or box2d32.h)"
#endif

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hooks.h"
#include "reports.c"
#include "world.c"
#include "shapes.c"
#include "bodies.c"
#include "joints.c"
#include "capture.c"
#include "lookup.c"

#endif /* BOX2SCENE_BOX2D3_ADAPTER_C */
