/*
 * Calm scenes, and where their bodies are as they evolve, for comparing the worlds two
 * Box2D v3 adapters build from one scene (box2d3_calm_trajectories.c writes v3.1's,
 * box2d32_agrees_with_box2d3_test.c compares v3.2's with them). Calm: nothing collides
 * hard, nothing spins fast, no joint starts violated, so that two solvers' small
 * differences stay small. Include after v3_support.h's adapter.
 */
#ifndef BOX2SCENE_CALM_SCENES_H
#define BOX2SCENE_CALM_SCENES_H

#define CALM_STEPS 300
#define CALM_EVERY 30 /* a sample every this many steps */
#define CALM_SAMPLES (CALM_STEPS / CALM_EVERY)

#define CALM_GROUND                                                                          \
    "<Shape Type='Polygon'><Vertices><Vertex>-50 -1</Vertex><Vertex>50 -1</Vertex>"          \
    "<Vertex>50 0</Vertex><Vertex>-50 0</Vertex></Vertices></Shape>"
#define CALM_BOX                                                                             \
    "<Shape Type='Polygon'><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>"    \
    "<Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>"
#define CALM_BALL "<Shape Type='Circle'><Radius>0.25</Radius><Position>0 0</Position></Shape>"

static const char* const calm_scenes[] = {
    /* a thrown box under gravity and damping */
    "<World Version='2'><Gravity>0 -10</Gravity><Shapes>" CALM_BOX "</Shapes><Fixtures>"
    "<Fixture><Shape>0</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
    "<Body Type='Dynamic'><Position>0 10</Position><LinearVelocity>3 4</LinearVelocity>"
    "<AngularVelocity>1</AngularVelocity><LinearDamping>0.1</LinearDamping>"
    "<AngularDamping>0.2</AngularDamping><Fixtures><ID>0</ID></Fixtures></Body>"
    "</Bodies></World>",
    /* a box settling on the ground, a ball rolling down a slope and on along the ground */
    "<World Version='2'><Gravity>0 -10</Gravity><Shapes>" CALM_GROUND CALM_BOX CALM_BALL
    "<Shape Type='Edge'><Vertex1>-10 3</Vertex1><Vertex2>-4 0</Vertex2></Shape></Shapes>"
    "<Fixtures><Fixture><Shape>0</Shape><Friction>0.6</Friction></Fixture>"
    "<Fixture><Shape>1</Shape><Density>1</Density><Friction>0.6</Friction></Fixture>"
    "<Fixture><Shape>2</Shape><Density>1</Density><Friction>0.6</Friction></Fixture>"
    "<Fixture><Shape>3</Shape><Friction>0.6</Friction></Fixture></Fixtures><Bodies>"
    "<Body Type='Static'><Fixtures><ID>0</ID><ID>3</ID></Fixtures></Body>"
    "<Body Type='Dynamic'><Position>20 0.5</Position><Fixtures><ID>1</ID></Fixtures></Body>"
    "<Body Type='Dynamic'><Position>-9 3.5</Position><Fixtures><ID>2</ID></Fixtures></Body>"
    "</Bodies></World>",
    /* a pendulum on a revolute joint, a box on a prismatic slide, a rigid rod */
    "<World Version='2'><Gravity>0 -10</Gravity><Shapes>" CALM_BOX CALM_BALL "</Shapes>"
    "<Fixtures><Fixture><Shape>0</Shape><Density>1</Density></Fixture>"
    "<Fixture><Shape>1</Shape><Density>1</Density></Fixture></Fixtures><Bodies>"
    "<Body Type='Static'><Position>0 10</Position></Body>"
    "<Body Type='Dynamic'><Position>2 10</Position><Fixtures><ID>1</ID></Fixtures></Body>"
    "<Body Type='Dynamic'><Position>10 10</Position><Fixtures><ID>0</ID></Fixtures></Body>"
    "<Body Type='Dynamic'><Position>-3 10</Position><Fixtures><ID>1</ID></Fixtures></Body>"
    "</Bodies><Joints>"
    "<Joint Type='Revolute'><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorB>-2 0"
    "</LocalAnchorB></Joint>"
    "<Joint Type='Prismatic'><BodyA>0</BodyA><BodyB>2</BodyB><LocalAnchorA>10 0"
    "</LocalAnchorA><LocalAxisA>1 -1</LocalAxisA></Joint>"
    "<Joint Type='Distance'><BodyA>0</BodyA><BodyB>3</BodyB><Length>3</Length></Joint>"
    "</Joints></World>",
};

#define CALM_SCENE_COUNT (sizeof calm_scenes / sizeof calm_scenes[0])

/* One sample of one body: where it is and how it is turned. */
typedef struct calm_sample {
    float x, y, angle;
} calm_sample;

/* How many samples calm_trajectories gives scene `i`: CALM_SAMPLES for each of its bodies. */
static inline uint32_t calm_body_count(size_t i) {
    b2s_scene* scene = load_text(calm_scenes[i]);
    uint32_t count = scene != NULL ? b2s_scene_get_view(scene)->body_count : 0;
    b2s_scene_free(scene);
    return count;
}

/* Every body of calm scene `i`, built by the adapter and stepped: `out` gets
 * CALM_SAMPLES samples per body, body by body. False when the build reports anything. */
static inline bool calm_trajectories(size_t i, calm_sample* out) {
    b2s_scene* scene = load_text(calm_scenes[i]);
    if (scene == NULL) {
        return false;
    }
    v3_world world = build_v3(scene);
    uint32_t bodies = b2s_scene_get_view(scene)->body_count;
    bool ok = world.built != NULL && world.built->reports.count == 0;
    for (int sample = 0; ok && sample < CALM_SAMPLES; ++sample) {
        step_v3(&world, CALM_EVERY);
        for (uint32_t b = 0; b < bodies; ++b) {
            b2BodyId body = world.built->bodies[b];
            b2Vec2 p = v3_position(body);
            b2Rot q = b2Body_GetRotation(body);
            calm_sample* s = &out[(size_t)b * CALM_SAMPLES + (size_t)sample];
            s->x = p.x;
            s->y = p.y;
            s->angle = atan2f(q.s, q.c);
        }
    }
    if (world.built != NULL && world.built->reports.count != 0) {
        print_reports(&world.built->reports);
    }
    free_v3(&world);
    b2s_scene_free(scene);
    return ok;
}

#endif /* BOX2SCENE_CALM_SCENES_H */
