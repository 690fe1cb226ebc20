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
 * start and end position; the SVG, drawn by the library (b2s_draw_svg), shows the start
 * (faint), the end (solid), the joints and each moving body's path, with a key.
 */
#ifdef SIMULATE_BOX2D32
#include <box2scene/box2d32.h>
#define ADAPTER(name) b2s_box2d32_##name
#define PROGRAM "simulate_v32"
#define ENGINE "box2d v3.2"
#define ENGINE_TITLE "Box2D v3.2"
#else
#include <box2scene/box2d3.h>
#define ADAPTER(name) b2s_box2d3_##name
#define PROGRAM "simulate_v3"
#define ENGINE "box2d v3"
#define ENGINE_TITLE "Box2D v3.1"
#endif
typedef ADAPTER(built) adapter_built;
typedef ADAPTER(reports) adapter_reports;
typedef ADAPTER(report) adapter_report;

#include <math.h>
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

/* What a run leaves: each body's origin sampled along it (sample after sample, one point per
 * body, as b2s_draw_svg takes them), and how far each body turned. v3 keeps a body's
 * rotation as a b2Rot, whose angle wraps at +-pi, so the turn is summed step by step to
 * count whole turns, as 2.4's unwrapped b2Body::GetAngle does in simulate.cpp. */
typedef struct run_result {
    b2s_vec2* samples;
    size_t sample_count;
    float* turned;
} run_result;

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

/* Where each body is now, indexed like the scene's bodies; not finite where the adapter
 * created no body, which the drawing leaves out. NULL when memory ran out. */
static b2s_pose* capture_poses(const adapter_built* built) {
    b2s_pose* poses = calloc(built->body_count + 1, sizeof(b2s_pose));
    for (uint32_t i = 0; poses != NULL && i < built->body_count; ++i) {
        const b2BodyId body = built->bodies[i];
        if (B2_IS_NULL(body)) {
            poses[i] = (b2s_pose){{NAN, NAN}, NAN};
            continue;
        }
        const b2Vec2 position = b2Body_GetPosition(body);
        poses[i] = (b2s_pose){{position.x, position.y}, b2Rot_GetAngle(b2Body_GetRotation(body))};
    }
    return poses;
}

static void sample_positions(const adapter_built* built, run_result* result) {
    b2s_vec2* sample = result->samples + result->sample_count++ * built->body_count;
    for (uint32_t i = 0; i < built->body_count; ++i) {
        const b2BodyId body = built->bodies[i];
        const b2Vec2 position = B2_IS_NULL(body) ? (b2Vec2){NAN, NAN} : b2Body_GetPosition(body);
        sample[i] = (b2s_vec2){position.x, position.y};
    }
}

static void free_run(run_result* result) {
    free(result->samples);
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
    result->samples = calloc(samples * bodies + 1, sizeof(b2s_vec2));
    result->sample_count = 0;
    result->turned = calloc(bodies + 1, sizeof(float));
    b2Rot* rotations = calloc(bodies + 1, sizeof(b2Rot));
    if (result->samples == NULL || result->turned == NULL || rotations == NULL) {
        free(rotations);
        return false;
    }
    for (uint32_t i = 0; i < bodies; ++i) {
        if (!B2_IS_NULL(built->bodies[i])) rotations[i] = b2Body_GetRotation(built->bodies[i]);
    }
    sample_positions(built, result);
    for (int step = 1; step <= steps; ++step) {
        b2World_Step(world, TIME_STEP, SUB_STEPS);
        for (uint32_t i = 0; i < bodies; ++i) {
            if (B2_IS_NULL(built->bodies[i])) continue;
            const b2Rot rotation = b2Body_GetRotation(built->bodies[i]);
            result->turned[i] += turn_between(rotations[i], rotation);
            rotations[i] = rotation;
        }
        if (step % TRAJECTORY_SAMPLE_STEPS == 0 || step == steps) {
            sample_positions(built, result);
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
                       const b2s_pose* start, const b2s_pose* end, const float* turned) {
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
        const b2s_vec2 from = start[i].position;
        const b2s_vec2 to = end[i].position;
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

/* The picture the library draws: the start faint, the end solid, the paths between. */
static bool draw(const b2s_scene* scene, const adapter_built* built, const options* opts,
                 const b2s_pose* start, const b2s_pose* end, const run_result* result) {
    char title[512];
    const char* slash = strrchr(opts->scene_path, '/');
    snprintf(title, sizeof title, "%s: %d steps of 1/60 s in " ENGINE_TITLE,
             slash != NULL ? slash + 1 : opts->scene_path, opts->steps);
    b2s_picture picture = b2s_picture_default();
    picture.title = title;
    picture.start = start;
    picture.end = end;
    picture.trajectories = result->samples;
    picture.trajectory_samples = result->sample_count;
    /* The joints the adapter created (it skips those Box2D v3 cannot hold). */
    bool* created = calloc(built->joint_count + 1, sizeof(bool));
    if (created == NULL) {
        fprintf(stderr, PROGRAM ": out of memory\n");
        return false;
    }
    for (uint32_t i = 0; i < built->joint_count; ++i) created[i] = !B2_IS_NULL(built->joints[i]);
    picture.joints_created = created;
    char* svg = NULL;
    size_t size = 0;
    b2s_error error;
    const b2s_code drawn = b2s_draw_svg(scene, &picture, &svg, &size, &error);
    free(created);
    if (drawn != B2S_CODE_OK) {
        fprintf(stderr, PROGRAM ": cannot draw the scene: %s\n", error.message);
        return false;
    }
    FILE* out = fopen(opts->svg_path, "wb");
    bool ok = out != NULL && fwrite(svg, 1, size, out) == size;
    if (out != NULL && fclose(out) != 0) ok = false;
    if (!ok) fprintf(stderr, PROGRAM ": cannot write %s\n", opts->svg_path);
    b2s_text_free(svg);
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
        b2s_pose* start = capture_poses(built);
        run_result result = {NULL, 0, NULL};
        const bool ran = start != NULL && run(world, built, opts.steps, &result);
        b2s_pose* end = capture_poses(built);
        if (!ran || end == NULL) {
            fprintf(stderr, PROGRAM ": out of memory\n");
        } else {
            printf("%d steps of %.4f s\n", opts.steps, (double)TIME_STEP);
            const int lost = print_table(view, built, start, end, result.turned);
            if (lost > 0) {
                fprintf(stderr,
                        PROGRAM ": %d bod%s ended with a non-finite position or angle: Box2D "
                        "could not hold this scene; no drawing written\n",
                        lost, lost == 1 ? "y" : "ies");
            } else if (draw(scene, built, &opts, start, end, &result)) {
                printf("wrote %s\n", opts.svg_path);
                status = 0;
            }
        }
        free(start);
        free(end);
        free_run(&result);
        ADAPTER(built_free)(built);
    }
    b2DestroyWorld(world);
    b2s_scene_free(scene);
    return status;
}
