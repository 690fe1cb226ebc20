/*
 * The working-range sweep both engines' tests run (range_sweep_test.cpp for Box2D 2.4,
 * v3_range_sweep_test.c for v3.1 and v3.2): small levels of two bodies and the joints between them,
 * each once as the file gives it (body B placed `violation` metres from satisfied) and once
 * satisfied, to be moved that far through the engine's own API after the build. Every
 * joint kind the engine has; body A static, free or pinned to the ground at its centre of
 * mass; boxes, centred and off-centre triangles; joints acting `lever` metres from the bodies'
 * origins (and far along their axes); four joints on one pair. Plain C, for both tests.
 */
#ifndef BOX2SCENE_RANGE_SWEEP_H
#define BOX2SCENE_RANGE_SWEEP_H

#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define SWEEP_STEPS 600
#define SWEEP_BOUND 1e4f /* m: farther than this from the origin is flying off */

/* The joints of a case: one kind, or four on one pair (distance, weld, line, friction). */
typedef enum sweep_joint {
    SWEEP_REVOLUTE,
    SWEEP_PRISMATIC,
    SWEEP_DISTANCE,
    SWEEP_PULLEY,
    SWEEP_LINE,
    SWEEP_WELD,
    SWEEP_FRICTION,
    SWEEP_WHEEL,
    SWEEP_ROPE,
    SWEEP_MOTOR,
    SWEEP_FOUR_ON_ONE_PAIR,
    SWEEP_JOINT_COUNT
} sweep_joint;

static const char* const sweep_joint_names[SWEEP_JOINT_COUNT] = {
    "revolute", "prismatic", "distance", "pulley", "line", "weld",
    "friction", "wheel",     "rope",     "motor",  "distance + weld + line + friction"};

typedef enum sweep_body_a { SWEEP_A_STATIC, SWEEP_A_FREE, SWEEP_A_PINNED, SWEEP_A_COUNT } sweep_body_a;

static const char* const sweep_body_a_names[SWEEP_A_COUNT] = {"static", "free", "pinned"};

typedef enum sweep_shape {
    SWEEP_BOX,
    SWEEP_TRIANGLE,
    SWEEP_OFF_CENTRE,
    SWEEP_SMALL_BALL,
    SWEEP_SHAPE_COUNT
} sweep_shape;

static const char* const sweep_shape_names[SWEEP_SHAPE_COUNT] = {
    "1 m box", "1 m triangle", "off-centre triangle", "20 cm ball"};

/* Each shape (1 m across, but for the ball), and its centroid: where a pin holds body A. */
static const char* const sweep_shape_xml[SWEEP_SHAPE_COUNT] = {
    "<Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>"
    "<Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>",
    "<Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 -0.288675</Vertex><Vertex>0.5 -0.288675</Vertex>"
    "<Vertex>0 0.57735</Vertex></Vertices></Shape>",
    "<Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>0 1</Vertex>"
    "</Vertices></Shape>",
    "<Shape Type=\"Circle\"><Radius>0.2</Radius><Position>0 0</Position></Shape>"};
static const float sweep_shape_centroid[SWEEP_SHAPE_COUNT][2] = {
    {0.0f, 0.0f}, {0.0f, 0.0f}, {1.0f / 3.0f, 1.0f / 3.0f}, {0.0f, 0.0f}};

#define SWEEP_VIOLATION_COUNT 6
static const float sweep_violations[SWEEP_VIOLATION_COUNT] = {0.0f, 0.1f, 0.5f, 2.0f, 10.0f, 50.0f};
#define SWEEP_LEVER_COUNT 3
static const float sweep_levers[SWEEP_LEVER_COUNT] = {0.5f, 2.0f, 10.0f};

typedef struct sweep_case {
    sweep_joint joint;
    sweep_body_a body_a;
    sweep_shape shape;
    float violation; /* m */
    float lever;     /* m: the anchors' distance from each body's origin */
} sweep_case;

#define SWEEP_CASE_COUNT \
    (SWEEP_JOINT_COUNT * SWEEP_A_COUNT * SWEEP_SHAPE_COUNT * SWEEP_VIOLATION_COUNT * SWEEP_LEVER_COUNT)

static inline sweep_case sweep_case_at(int i) {
    sweep_case c;
    c.lever = sweep_levers[i % SWEEP_LEVER_COUNT];
    i /= SWEEP_LEVER_COUNT;
    c.violation = sweep_violations[i % SWEEP_VIOLATION_COUNT];
    i /= SWEEP_VIOLATION_COUNT;
    c.shape = (sweep_shape)(i % SWEEP_SHAPE_COUNT);
    i /= SWEEP_SHAPE_COUNT;
    c.body_a = (sweep_body_a)(i % SWEEP_A_COUNT);
    i /= SWEEP_A_COUNT;
    c.joint = (sweep_joint)i;
    return c;
}

/* Bodies: 0 the ground (no fixture), 1 body A at the origin, 2 body B. Joints: the pin (when
 * body A is pinned), then the case's joints. */
#define SWEEP_BODY_A 1
#define SWEEP_BODY_B 2

static inline int sweep_first_joint(const sweep_case* c) {
    return c->body_a == SWEEP_A_PINNED ? 1 : 0;
}

static inline int sweep_joint_count(const sweep_case* c) {
    return c->joint == SWEEP_FOUR_ON_ONE_PAIR ? 4 : 1;
}

/* How body B is moved from where the joints are satisfied: across the axis (1, 0) for the
 * joints that hold a point or an axis, along the rod for distance and rope, down for the
 * pulley. */
static inline void sweep_displacement(const sweep_case* c, float* dx, float* dy) {
    *dx = 0.0f;
    *dy = 0.0f;
    switch (c->joint) {
    case SWEEP_DISTANCE:
    case SWEEP_ROPE: *dx = c->violation; break;
    case SWEEP_PULLEY: *dy = -c->violation; break;
    default: *dy = c->violation; break;
    }
}

static inline int sweep_joint_xml(char* out, size_t size, const char* type, const char* fields) {
    return snprintf(out, size, "<Joint Type=\"%s\"><BodyA>1</BodyA><BodyB>2</BodyB>%s</Joint>",
                    type, fields);
}

/* The joints of the case, satisfied with body B at (2 lever, 0): a point joint's anchor at
 * (lever, 0), an axis along x, a rod between the origins. */
static inline void sweep_joints_xml(const sweep_case* c, char* out, size_t size) {
    char anchors[160], fields[400];
    float l = c->lever;
    snprintf(anchors, sizeof anchors,
             "<LocalAnchorA>%.9g 0</LocalAnchorA><LocalAnchorB>%.9g 0</LocalAnchorB>",
             (double)l, (double)-l);
    const char* axis = "<LocalAxisA>1 0</LocalAxisA>";
    size_t used = 0;
    switch (c->joint) {
    case SWEEP_REVOLUTE: sweep_joint_xml(out, size, "Revolute", anchors); return;
    case SWEEP_PRISMATIC:
        snprintf(fields, sizeof fields, "%s%s", anchors, axis);
        sweep_joint_xml(out, size, "Prismatic", fields);
        return;
    case SWEEP_LINE:
        snprintf(fields, sizeof fields, "%s%s", anchors, axis);
        sweep_joint_xml(out, size, "Line", fields);
        return;
    case SWEEP_WHEEL:
        snprintf(fields, sizeof fields, "%s%s", anchors, axis);
        sweep_joint_xml(out, size, "Wheel", fields);
        return;
    case SWEEP_WELD: sweep_joint_xml(out, size, "Weld", anchors); return;
    case SWEEP_FRICTION:
        snprintf(fields, sizeof fields, "%s<MaxForce>10</MaxForce><MaxTorque>10</MaxTorque>",
                 anchors);
        sweep_joint_xml(out, size, "Friction", fields);
        return;
    case SWEEP_DISTANCE:
        snprintf(fields, sizeof fields, "<Length>%.9g</Length>", (double)(2.0f * l));
        sweep_joint_xml(out, size, "Distance", fields);
        return;
    case SWEEP_ROPE:
        snprintf(fields, sizeof fields,
                 "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>"
                 "<MaxLength>%.9g</MaxLength>",
                 (double)(2.0f * l));
        sweep_joint_xml(out, size, "Rope", fields);
        return;
    case SWEEP_PULLEY:
        snprintf(fields, sizeof fields,
                 "<GroundAnchorA>0 5</GroundAnchorA><GroundAnchorB>%.9g 5</GroundAnchorB>"
                 "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>"
                 "<LengthA>5</LengthA><LengthB>5</LengthB>",
                 (double)(2.0f * l));
        sweep_joint_xml(out, size, "Pulley", fields);
        return;
    case SWEEP_MOTOR:
        snprintf(fields, sizeof fields,
                 "<LinearOffset>%.9g 0</LinearOffset><MaxForce>50</MaxForce>"
                 "<MaxTorque>50</MaxTorque>",
                 (double)(2.0f * l));
        sweep_joint_xml(out, size, "Motor", fields);
        return;
    case SWEEP_FOUR_ON_ONE_PAIR:
        snprintf(fields, sizeof fields, "<Length>%.9g</Length>", (double)(2.0f * l));
        used += (size_t)sweep_joint_xml(out + used, size - used, "Distance", fields);
        used += (size_t)sweep_joint_xml(out + used, size - used, "Weld", anchors);
        snprintf(fields, sizeof fields, "%s%s", anchors, axis);
        used += (size_t)sweep_joint_xml(out + used, size - used, "Line", fields);
        snprintf(fields, sizeof fields, "%s<MaxForce>10</MaxForce><MaxTorque>10</MaxTorque>",
                 anchors);
        sweep_joint_xml(out + used, size - used, "Friction", fields);
        return;
    case SWEEP_JOINT_COUNT: break;
    }
}

/* The level of case `c` with body B moved by (dx, dy) from where its joints are satisfied. */
static inline void sweep_scene_xml(const sweep_case* c, float dx, float dy, char* out,
                                   size_t size) {
    char pin[240] = "", joints[1600];
    const float* centroid = sweep_shape_centroid[c->shape];
    if (c->body_a == SWEEP_A_PINNED) {
        snprintf(pin, sizeof pin,
                 "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB>"
                 "<LocalAnchorA>%.9g %.9g</LocalAnchorA><LocalAnchorB>%.9g %.9g</LocalAnchorB>"
                 "</Joint>",
                 (double)centroid[0], (double)centroid[1], (double)centroid[0],
                 (double)centroid[1]);
    }
    sweep_joints_xml(c, joints, sizeof joints);
    snprintf(out, size,
             "<World Version=\"2\"><Gravity>0 -10</Gravity>"
             "<Shapes>%s</Shapes>"
             "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures>"
             "<Bodies><Body Type=\"Static\"/>"
             "<Body Type=\"%s\"><Fixtures><ID>0</ID></Fixtures></Body>"
             "<Body Type=\"Dynamic\"><Position>%.9g %.9g</Position><Fixtures><ID>0</ID>"
             "</Fixtures></Body></Bodies>"
             "<Joints>%s%s</Joints></World>",
             sweep_shape_xml[c->shape], c->body_a == SWEEP_A_STATIC ? "Static" : "Dynamic",
             (double)(2.0f * c->lever + dx), (double)dy, pin, joints);
}

/* What became of a case: held (finite and within SWEEP_BOUND for SWEEP_STEPS steps), the
 * adapter refused one of its joints (beyond-box2d-range), or the engine did not hold it
 * (non-finite, flown off, or an assertion: the child that ran it died). */
typedef enum sweep_outcome {
    SWEEP_HELD = 0,
    SWEEP_LOST = 1,
    SWEEP_REFUSED = 2,
    SWEEP_NOT_MEASURED = 3, /* the adapter refuses the satisfied level already */
    SWEEP_NOT_LOADED = 4
} sweep_outcome;

/* Held and built counts per joint kind and violation, for the table. */
typedef struct sweep_table {
    /* the engine, satisfied and moved: cases the adapter built satisfied, and those held */
    int measured[SWEEP_JOINT_COUNT][SWEEP_VIOLATION_COUNT];
    int held[SWEEP_JOINT_COUNT][SWEEP_VIOLATION_COUNT];
    int built[SWEEP_JOINT_COUNT][SWEEP_VIOLATION_COUNT]; /* the adapter, from the file */
    int cases[SWEEP_JOINT_COUNT][SWEEP_VIOLATION_COUNT];
} sweep_table;

static inline int sweep_violation_index(float v) {
    for (int i = 0; i < SWEEP_VIOLATION_COUNT; ++i) {
        if (sweep_violations[i] == v) {
            return i;
        }
    }
    return 0;
}

/* The table as docs/working-range.md shows it: per kind and initial violation, how many of
 * the cases the engine holds (of those it could be measured on: built satisfied, then
 * moved), and how many the adapter builds (each of which it holds). */
static inline void sweep_print_table(const char* engine, const sweep_table* t,
                                     const bool has[SWEEP_JOINT_COUNT]) {
    printf("\n%s, %d cases each: held by the engine of measured / built by the adapter\n\n",
           engine, t->cases[0][0]);
    printf("| joints | ");
    for (int v = 0; v < SWEEP_VIOLATION_COUNT; ++v) {
        printf("%g m | ", (double)sweep_violations[v]);
    }
    printf("\n|---|");
    for (int v = 0; v < SWEEP_VIOLATION_COUNT; ++v) {
        printf("---|");
    }
    printf("\n");
    for (int j = 0; j < SWEEP_JOINT_COUNT; ++j) {
        if (!has[j]) {
            continue;
        }
        printf("| %s | ", sweep_joint_names[j]);
        for (int v = 0; v < SWEEP_VIOLATION_COUNT; ++v) {
            printf("%d of %d / %d | ", t->held[j][v], t->measured[j][v], t->built[j][v]);
        }
        printf("\n");
    }
}

/* Runs `run` on case `c` in a child process: its exit code, or SWEEP_LOST when it died (an
 * assertion). `run` ends the child with _exit. */
static inline int sweep_in_child(void (*run)(const sweep_case*), const sweep_case* c) {
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        run(c);
        _exit(SWEEP_LOST);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : SWEEP_LOST;
}

static inline void sweep_describe(const char* what, const sweep_case* c) {
    fprintf(stderr, "%s: %s, body A %s, %s, violation %g m, lever %g m\n", what,
            sweep_joint_names[c->joint], sweep_body_a_names[c->body_a],
            sweep_shape_names[c->shape], (double)c->violation, (double)c->lever);
}

/* One engine's sweep: every case of a joint kind it `has`, once through `run_moved` (the
 * engine: built satisfied, then moved) and once through `run_built` (the adapter, from the
 * file), each in a child. Fails a case the adapter builds and the engine does not hold, and
 * a satisfied case the adapter refuses unless `may_refuse_satisfied` says the engine was
 * measured not to hold it; prints the table. Returns how many cases failed. */
static inline int sweep_engine(const char* engine, void (*run_moved)(const sweep_case*),
                               void (*run_built)(const sweep_case*),
                               bool has[SWEEP_JOINT_COUNT],
                               bool (*may_refuse_satisfied)(const sweep_case*)) {
    static sweep_table table;
    memset(&table, 0, sizeof table);
    int failed = 0;
    for (int i = 0; i < SWEEP_CASE_COUNT; ++i) {
        sweep_case c = sweep_case_at(i);
        if (!has[c.joint]) {
            continue;
        }
        int v = sweep_violation_index(c.violation);
        int moved = sweep_in_child(run_moved, &c);
        int built = sweep_in_child(run_built, &c);
        table.cases[c.joint][v] += 1;
        table.measured[c.joint][v] += moved == SWEEP_HELD || moved == SWEEP_LOST;
        table.held[c.joint][v] += moved == SWEEP_HELD;
        table.built[c.joint][v] += built == SWEEP_HELD;
        if (built != SWEEP_HELD && built != SWEEP_REFUSED) {
            sweep_describe(built == SWEEP_LOST ? "built, not held" : "not loaded", &c);
            failed += 1;
        } else if (built == SWEEP_REFUSED && c.violation == 0.0f && !may_refuse_satisfied(&c)) {
            sweep_describe("satisfied, refused", &c);
            failed += 1;
        } else if (built == SWEEP_REFUSED && moved == SWEEP_HELD) {
            sweep_describe("refused, though the engine holds it", &c);
        }
    }
    sweep_print_table(engine, &table, has);
    return failed;
}

#endif /* BOX2SCENE_RANGE_SWEEP_H */
