/*
 * simulate_v3 and simulate_v32: load a Box2Scene file, build a Box2D v3 world from it, run
 * it, and show what happened: examples/simulate.cpp for Box2D v3.1 (simulate_v3) and v3.2
 * (simulate_v32, this file compiled with SIMULATE_BOX2D32 against v3.2: the two Box2D
 * versions cannot share a program), in C.
 *
 *     simulate_v3 [SCENE] [--steps N] [--svg OUT.svg]
 *     simulate_v32 [SCENE] [--steps N] [--svg OUT.svg]
 *
 * SCENE defaults to the bundled showcase, N to 300 steps of 1/60 s, OUT.svg to the program's
 * name with .svg in the build folder beside it (build/examples/).
 * Prints the load's warnings, what Box2D v3 could not represent, and a table of every body's
 * start and end position; the SVG shows the start (faint), the end (solid), the joints and
 * each moving body's trajectory.
 */
#ifdef SIMULATE_BOX2D32
#include <box2scene/box2d32.h>
#define ADAPTER(name) b2s_box2d32_##name
#define PROGRAM "simulate_v32"
#define ENGINE "box2d v3.2"
/* v3.2 keeps a joint's anchors as the origins of its local frames. */
static b2Vec2 local_anchor_a(b2JointId joint) {
    return b2Joint_GetLocalFrameA(joint).p;
}
static b2Vec2 local_anchor_b(b2JointId joint) {
    return b2Joint_GetLocalFrameB(joint).p;
}
#else
#include <box2scene/box2d3.h>
#define ADAPTER(name) b2s_box2d3_##name
#define PROGRAM "simulate_v3"
#define ENGINE "box2d v3"
static b2Vec2 local_anchor_a(b2JointId joint) {
    return b2Joint_GetLocalAnchorA(joint);
}
static b2Vec2 local_anchor_b(b2JointId joint) {
    return b2Joint_GetLocalAnchorB(joint);
}
#endif
typedef ADAPTER(built) adapter_built;
typedef ADAPTER(reports) adapter_reports;
typedef ADAPTER(report) adapter_report;

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TIME_STEP (1.0f / 60.0f)
/* Box2D v3's recommended sub-step count (it replaces 2.4's velocity and position iterations). */
#define SUB_STEPS 4
/* Every 5th step is enough for a smooth trajectory and keeps the SVG small. */
#define TRAJECTORY_SAMPLE_STEPS 5
#define MAX_STEPS 1000000

typedef struct options {
    const char* scene_path;
    int steps;
    const char* svg_path;
    bool help;
} options;

/* Where each body is at one instant (indexed like the scene's bodies; unused where the adapter
 * created no body), and each created joint's two anchors in world coordinates. */
typedef struct frame {
    b2Transform* bodies;
    b2Vec2 (*joints)[2];
    uint32_t joint_count;
} frame;

/* A body's origin sampled along the run. */
typedef struct trajectory {
    b2Vec2* points;
    uint32_t count;
} trajectory;

/* What a run leaves: each body's trajectory, and how far it turned. v3 keeps a body's
 * rotation as a b2Rot, whose angle wraps at +-pi, so the turn is summed step by step to
 * count whole turns, as 2.4's unwrapped b2Body::GetAngle does in simulate.cpp. */
typedef struct run_result {
    trajectory* paths;
    float* turned;
} run_result;

/* A growing piece of text; `failed` once memory ran out. */
typedef struct text {
    char* data;
    size_t length;
    size_t capacity;
    bool failed;
} text;

static void print_usage(FILE* to) {
    fprintf(to, "usage: " PROGRAM " [SCENE] [--steps N] [--svg OUT.svg]\n");
}

static bool parse_step_count(const char* value, int* steps) {
    char* end = NULL;
    const long parsed = strtol(value, &end, 10);
    if (end == value || *end != '\0' || parsed < 0 || parsed > MAX_STEPS) return false;
    *steps = (int)parsed;
    return true;
}

static bool parse_options(int argc, char** argv, options* out) {
    options result = {BOX2SCENE_EXAMPLE_SCENE, 300, BOX2SCENE_EXAMPLE_SVG, false};
    bool scene_given = false;
    for (int i = 1; i < argc; ++i) {
        const char* arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            result.help = true;
        } else if (strcmp(arg, "--steps") == 0 && has_value) {
            if (!parse_step_count(argv[++i], &result.steps)) {
                fprintf(stderr, PROGRAM ": --steps wants a whole number from 0 to 1000000\n");
                return false;
            }
        } else if (strcmp(arg, "--svg") == 0 && has_value) {
            result.svg_path = argv[++i];
        } else if (strncmp(arg, "--", 2) != 0 && !scene_given) {
            result.scene_path = arg;
            scene_given = true;
        } else {
            print_usage(stderr);
            return false;
        }
    }
    *out = result;
    return true;
}

static b2s_scene* load_scene(const char* path) {
    b2s_scene* scene = NULL;
    b2s_error error;
    if (b2s_load_file(path, NULL, &scene, &error) != B2S_CODE_OK) {
        fprintf(stderr, "%s:%u:%u: error[%s]: %s\n", path, error.line, error.column,
                b2s_code_name(error.code), error.message);
    }
    return scene;
}

static void print_warnings(const char* path, const b2s_scene_view* view) {
    for (uint32_t i = 0; i < view->diagnostic_count; ++i) {
        const b2s_diagnostic* warning = &view->diagnostics[i];
        fprintf(stderr, "%s:%u:%u: warning[%s]: %s\n", path, warning->line, warning->column,
                b2s_code_name(warning->code), warning->message);
    }
}

static void print_reports(const adapter_reports* reports) {
    for (uint32_t i = 0; i < reports->count; ++i) {
        const adapter_report* report = &reports->items[i];
        fprintf(stderr, ENGINE ": not represented[%s]: %s %u%s%s%s: %s\n",
                b2s_code_name(report->code), report->object, report->index,
                report->name ? " \"" : "", report->name ? report->name : "",
                report->name ? "\"" : "", report->message);
    }
}

static void print_gravity(const b2s_scene_view* view, b2Vec2 gravity) {
    printf("gravity (%g, %g) m/s^2, %s\n", (double)gravity.x, (double)gravity.y,
           view->gravity_given ? "from the scene" : "the default: the scene gives none");
}

static frame capture_frame(const adapter_built* built) {
    frame captured = {calloc(built->body_count + 1, sizeof(b2Transform)),
                      calloc(built->joint_count + 1, sizeof(b2Vec2[2])), 0};
    if (captured.bodies == NULL || captured.joints == NULL) return captured;
    for (uint32_t i = 0; i < built->body_count; ++i) {
        if (!B2_IS_NULL(built->bodies[i])) {
            captured.bodies[i] = b2Body_GetTransform(built->bodies[i]);
        }
    }
    /* Every v3 joint is drawn straight between its body anchors (revolute and weld anchors
     * coincide, which shows as a dot); v3 has no pulley. */
    for (uint32_t i = 0; i < built->joint_count; ++i) {
        const b2JointId joint = built->joints[i];
        if (B2_IS_NULL(joint)) continue;
        b2Vec2* anchors = captured.joints[captured.joint_count++];
        anchors[0] = b2Body_GetWorldPoint(b2Joint_GetBodyA(joint), local_anchor_a(joint));
        anchors[1] = b2Body_GetWorldPoint(b2Joint_GetBodyB(joint), local_anchor_b(joint));
    }
    return captured;
}

static void free_frame(frame* captured) {
    free(captured->bodies);
    free(captured->joints);
}

static void sample_positions(const adapter_built* built, trajectory* paths) {
    for (uint32_t i = 0; i < built->body_count; ++i) {
        if (!B2_IS_NULL(built->bodies[i])) {
            paths[i].points[paths[i].count++] = b2Body_GetPosition(built->bodies[i]);
        }
    }
}

static void free_run(run_result* result, uint32_t body_count) {
    for (uint32_t i = 0; result->paths != NULL && i < body_count; ++i) {
        free(result->paths[i].points);
    }
    free(result->paths);
    free(result->turned);
}

/* Steps the world; false when memory ran out. */
/* How far `to` is turned from `from`, within +-pi (b2RelativeAngle takes its rotations in
 * the other order in v3.2 than in v3.1). */
static float turn_between(b2Rot from, b2Rot to) {
    return atan2f(from.c * to.s - from.s * to.c, from.c * to.c + from.s * to.s);
}

static bool run(b2WorldId world, const adapter_built* built, int steps, run_result* result) {
    const uint32_t bodies = built->body_count;
    const size_t samples = (size_t)steps / TRAJECTORY_SAMPLE_STEPS + 2;
    result->paths = calloc(bodies + 1, sizeof(trajectory));
    result->turned = calloc(bodies + 1, sizeof(float));
    b2Rot* rotations = calloc(bodies + 1, sizeof(b2Rot));
    bool ok = result->paths != NULL && result->turned != NULL && rotations != NULL;
    for (uint32_t i = 0; ok && i < bodies; ++i) {
        result->paths[i].points = malloc(samples * sizeof(b2Vec2));
        ok = result->paths[i].points != NULL;
        if (!B2_IS_NULL(built->bodies[i])) rotations[i] = b2Body_GetRotation(built->bodies[i]);
    }
    if (!ok) {
        free(rotations);
        return false;
    }
    sample_positions(built, result->paths);
    for (int step = 1; step <= steps; ++step) {
        b2World_Step(world, TIME_STEP, SUB_STEPS);
        for (uint32_t i = 0; i < bodies; ++i) {
            if (B2_IS_NULL(built->bodies[i])) continue;
            const b2Rot rotation = b2Body_GetRotation(built->bodies[i]);
            result->turned[i] += turn_between(rotations[i], rotation);
            rotations[i] = rotation;
        }
        if (step % TRAJECTORY_SAMPLE_STEPS == 0 || step == steps) {
            sample_positions(built, result->paths);
        }
    }
    free(rotations);
    return true;
}

static const char* body_kind_name(uint32_t kind) {
    switch (kind) {
    case B2S_BODY_KIND_STATIC: return "static";
    case B2S_BODY_KIND_KINEMATIC: return "kinematic";
    case B2S_BODY_KIND_DYNAMIC: return "dynamic";
    default: return "unknown";
    }
}

static const char* body_name(const b2s_body* body) { return body->name ? body->name : "-"; }

/* Prints where each body started and ended; returns how many ended non-finite. */
static int print_table(const b2s_scene_view* view, const adapter_built* built,
                       const frame* start, const frame* end, const float* turned) {
    int non_finite = 0;
    size_t name_width = 4;
    for (uint32_t i = 0; i < view->body_count; ++i) {
        const size_t length = strlen(body_name(&view->bodies[i]));
        if (length > name_width) name_width = length;
    }
    const int width = (int)name_width;
    printf("%5s  %-*s  %-9s  %-18s  %-18s  %s\n", "index", width, "name", "type", "start (m)",
           "end (m)", "turned (rad)");
    for (uint32_t i = 0; i < view->body_count; ++i) {
        const b2s_body* body = &view->bodies[i];
        printf("%5u  %-*s  %-9s  ", i, width, body_name(body), body_kind_name(body->kind));
        if (B2_IS_NULL(built->bodies[i])) {
            printf("not created\n");
            continue;
        }
        const b2Vec2 from = start->bodies[i].p;
        const b2Vec2 to = end->bodies[i].p;
        if (!(isfinite(to.x) && isfinite(to.y) && isfinite(turned[i]))) {
            printf("(%7.2f, %7.2f)  not finite: Box2D lost this body\n", (double)from.x,
                   (double)from.y);
            non_finite += 1;
            continue;
        }
        printf("(%7.2f, %7.2f)  (%7.2f, %7.2f)  %12.2f\n", (double)from.x, (double)from.y,
               (double)to.x, (double)to.y, (double)turned[i]);
    }
    return non_finite;
}

static void append(text* out, const char* format, ...) {
    if (out->failed) return;
    va_list args;
    va_start(args, format);
    va_list again;
    va_copy(again, args);
    const int needed = vsnprintf(NULL, 0, format, args);
    va_end(args);
    if (needed < 0 || out->length + (size_t)needed + 1 > out->capacity) {
        const size_t capacity = 2 * (out->capacity + (needed < 0 ? 0 : (size_t)needed)) + 256;
        char* grown = needed < 0 ? NULL : realloc(out->data, capacity);
        if (grown == NULL) {
            out->failed = true;
            va_end(again);
            return;
        }
        out->data = grown;
        out->capacity = capacity;
    }
    vsnprintf(out->data + out->length, out->capacity - out->length, format, again);
    va_end(again);
    out->length += (size_t)needed;
}

static void append_escaped_xml(text* out, const char* value) {
    for (const char* c = value; *c != '\0'; ++c) {
        switch (*c) {
        case '&': append(out, "&amp;"); break;
        case '<': append(out, "&lt;"); break;
        case '>': append(out, "&gt;"); break;
        case '"': append(out, "&quot;"); break;
        default: append(out, "%c", *c);
        }
    }
}

/* An SVG drawing in world coordinates (metres, Y up). Points are flipped to SVG's Y down as
 * they are written, and the view box is fitted to everything drawn. */
typedef struct svg {
    text body;
    bool empty;
    b2Vec2 lower;
    b2Vec2 upper;
} svg;

/* SVG's Y axis points down. 0 - y rather than -y, so that y = 0 prints "0", not "-0". */
static double flipped(float y) { return (double)(0.0f - y); }

static void svg_include(svg* drawing, b2Vec2 point) {
    drawing->lower = drawing->empty ? point : b2Min(drawing->lower, point);
    drawing->upper = drawing->empty ? point : b2Max(drawing->upper, point);
    drawing->empty = false;
}

static void svg_open_group(svg* drawing, const char* css_class, const char* title) {
    append(&drawing->body, "<g class=\"%s\">", css_class);
    if (title != NULL && title[0] != '\0') {
        append(&drawing->body, "<title>");
        append_escaped_xml(&drawing->body, title);
        append(&drawing->body, "</title>");
    }
    append(&drawing->body, "\n");
}

static void svg_close_group(svg* drawing) { append(&drawing->body, "</g>\n"); }

static void svg_circle(svg* drawing, b2Vec2 centre, float radius) {
    svg_include(drawing, (b2Vec2){centre.x - radius, centre.y - radius});
    svg_include(drawing, (b2Vec2){centre.x + radius, centre.y + radius});
    append(&drawing->body, "<circle cx=\"%g\" cy=\"%g\" r=\"%g\"/>\n", (double)centre.x,
           flipped(centre.y), (double)radius);
}

/* `points` taken through `xf` (the identity for points already in world coordinates). */
static void svg_shape(svg* drawing, const char* element, b2Transform xf, const b2Vec2* points,
                      int count) {
    append(&drawing->body, "<%s points=\"", element);
    for (int i = 0; i < count; ++i) {
        const b2Vec2 point = b2TransformPoint(xf, points[i]);
        svg_include(drawing, point);
        append(&drawing->body, "%g,%g ", (double)point.x, flipped(point.y));
    }
    append(&drawing->body, "\"/>\n");
}

static void svg_polyline(svg* drawing, b2Transform xf, const b2Vec2* points, int count) {
    svg_shape(drawing, "polyline", xf, points, count);
}

/* Faint start, solid end; colours by body type; joints red, trajectories orange. */
static const char* const svg_style = "g{stroke-width:0.05;stroke-linejoin:round}"
                                     ".start{opacity:0.25}"
                                     ".static{fill:#c8c8c8;stroke:#606060}"
                                     ".kinematic{fill:#b8e0b0;stroke:#3a7a30}"
                                     ".dynamic{fill:#a8c8f0;stroke:#2a5a9a}"
                                     ".joints{stroke:#d03030;fill:#d03030}"
                                     ".joints polyline{fill:none}"
                                     ".trajectories{stroke:#f08a00;stroke-width:0.04;fill:none}";

/* A circle carries a radius line so that its rotation shows. */
static void draw_circle(svg* drawing, b2Circle circle, b2Transform xf) {
    const b2Vec2 ends[2] = {circle.center, {circle.center.x + circle.radius, circle.center.y}};
    svg_circle(drawing, b2TransformPoint(xf, circle.center), circle.radius);
    svg_polyline(drawing, xf, ends, 2);
}

/* Every kind of shape the adapter creates. A v3 chain is a shape per segment, each drawn on
 * its own; the ghost vertices that only guide collisions are not drawn. */
static void draw_shape(svg* drawing, b2ShapeId shape, b2Transform xf) {
    switch (b2Shape_GetType(shape)) {
    case b2_circleShape: draw_circle(drawing, b2Shape_GetCircle(shape), xf); break;
    case b2_polygonShape: {
        const b2Polygon polygon = b2Shape_GetPolygon(shape);
        svg_shape(drawing, "polygon", xf, polygon.vertices, polygon.count);
        break;
    }
    case b2_segmentShape: {
        const b2Segment segment = b2Shape_GetSegment(shape);
        svg_polyline(drawing, xf, &segment.point1, 2);
        break;
    }
    case b2_chainSegmentShape: {
        const b2Segment segment = b2Shape_GetChainSegment(shape).segment;
        svg_polyline(drawing, xf, &segment.point1, 2);
        break;
    }
    /* The adapter makes no capsule (a Box2Scene file has none): its axis will do. */
    case b2_capsuleShape: {
        const b2Capsule capsule = b2Shape_GetCapsule(shape);
        svg_polyline(drawing, xf, &capsule.center1, 2);
        break;
    }
    case b2_shapeTypeCount: break;
    }
}

static void draw_bodies(svg* drawing, const b2s_scene_view* view, const adapter_built* built,
                        const frame* captured) {
    for (uint32_t i = 0; i < built->body_count; ++i) {
        const b2BodyId body = built->bodies[i];
        if (B2_IS_NULL(body)) continue;
        svg_open_group(drawing, body_kind_name(view->bodies[i].kind), body_name(&view->bodies[i]));
        const int count = b2Body_GetShapeCount(body);
        b2ShapeId* shapes = malloc(((size_t)count + 1) * sizeof(b2ShapeId));
        if (shapes == NULL) {
            drawing->body.failed = true;
            return;
        }
        const int found = b2Body_GetShapes(body, shapes, count);
        for (int s = 0; s < found; ++s) draw_shape(drawing, shapes[s], captured->bodies[i]);
        free(shapes);
        svg_close_group(drawing);
    }
}

static void draw_joints(svg* drawing, const frame* captured) {
    const float anchor_radius = 0.08f;
    svg_open_group(drawing, "joints", NULL);
    for (uint32_t i = 0; i < captured->joint_count; ++i) {
        svg_polyline(drawing, b2Transform_identity, captured->joints[i], 2);
        svg_circle(drawing, captured->joints[i][0], anchor_radius);
        svg_circle(drawing, captured->joints[i][1], anchor_radius);
    }
    svg_close_group(drawing);
}

static void draw_trajectories(svg* drawing, const b2s_scene_view* view, const trajectory* paths) {
    svg_open_group(drawing, "trajectories", NULL);
    for (uint32_t i = 0; i < view->body_count; ++i) {
        if (view->bodies[i].kind != B2S_BODY_KIND_STATIC && paths[i].count > 0) {
            svg_polyline(drawing, b2Transform_identity, paths[i].points, (int)paths[i].count);
        }
    }
    svg_close_group(drawing);
}

/* The whole document; its text is NULL when memory ran out. */
static text render_svg(const b2s_scene_view* view, const adapter_built* built,
                       const frame* start, const frame* end, const trajectory* paths) {
    svg drawing = {{NULL, 0, 0, false}, true, {0.0f, 0.0f}, {0.0f, 0.0f}};
    svg_open_group(&drawing, "start", NULL);
    draw_bodies(&drawing, view, built, start);
    draw_joints(&drawing, start);
    svg_close_group(&drawing);
    draw_trajectories(&drawing, view, paths);
    svg_open_group(&drawing, "end", NULL);
    draw_bodies(&drawing, view, built, end);
    draw_joints(&drawing, end);
    svg_close_group(&drawing);

    const float margin = 1.0f;
    const double x = (double)(drawing.lower.x - margin);
    const double y = flipped(drawing.upper.y) - (double)margin;
    const double width = (double)(drawing.upper.x - drawing.lower.x + 2 * margin);
    const double height = (double)(drawing.upper.y - drawing.lower.y + 2 * margin);
    const double pixels_per_metre = 20.0;
    text document = {NULL, 0, 0, false};
    append(&document,
           "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%g %g %g %g\" width=\"%g\" "
           "height=\"%g\">\n<style>%s</style>\n"
           "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"white\"/>\n%s</svg>\n",
           x, y, width, height, width * pixels_per_metre, height * pixels_per_metre, svg_style,
           x, y, width, height, drawing.body.data != NULL ? drawing.body.data : "");
    if (drawing.body.failed) document.failed = true;
    free(drawing.body.data);
    return document;
}

static bool write_file(const char* path, const text* content) {
    FILE* out = fopen(path, "wb");
    bool ok = out != NULL && !content->failed &&
              fwrite(content->data, 1, content->length, out) == content->length;
    if (out != NULL && fclose(out) != 0) ok = false;
    if (!ok) fprintf(stderr, PROGRAM ": cannot write %s\n", path);
    return ok;
}

int main(int argc, char** argv) {
    options opts;
    if (!parse_options(argc, argv, &opts)) return 2;
    if (opts.help) {
        print_usage(stdout);
        return 0;
    }

    b2s_scene* scene = load_scene(opts.scene_path);
    if (scene == NULL) return 1;
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    print_warnings(opts.scene_path, view);

    /* The scene decides gravity; a file without <Gravity> gets Earth's, Y up. */
    const b2Vec2 default_gravity = {0.0f, -10.0f};
    print_gravity(view, ADAPTER(scene_gravity)(scene, default_gravity));
    const b2WorldDef def = ADAPTER(world_def)(scene, default_gravity);
    const b2WorldId world = b2CreateWorld(&def);
    adapter_built* built = ADAPTER(build_world)(scene, world);
    int status = 1;
    if (built == NULL) {
        fprintf(stderr, PROGRAM ": out of memory\n");
    } else {
        print_reports(&built->reports);
        frame start = capture_frame(built);
        run_result result = {NULL, NULL};
        const bool ran = start.bodies != NULL && start.joints != NULL &&
                         run(world, built, opts.steps, &result);
        frame end = capture_frame(built);
        if (!ran || end.bodies == NULL || end.joints == NULL) {
            fprintf(stderr, PROGRAM ": out of memory\n");
        } else {
            printf("%d steps of %.4f s\n", opts.steps, (double)TIME_STEP);
            const int lost = print_table(view, built, &start, &end, result.turned);
            if (lost > 0) {
                fprintf(stderr,
                        PROGRAM ": %d bod%s ended with a non-finite position or angle: Box2D "
                        "could not hold this scene; no drawing written\n",
                        lost, lost == 1 ? "y" : "ies");
            } else {
                text document = render_svg(view, built, &start, &end, result.paths);
                if (write_file(opts.svg_path, &document)) {
                    printf("wrote %s\n", opts.svg_path);
                    status = 0;
                }
                free(document.data);
            }
        }
        free_frame(&start);
        free_frame(&end);
        free_run(&result, built->body_count);
        ADAPTER(built_free)(built);
    }
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return status;
}
