/*
 * The port of docs/ports.md (examples/port_v31.c, which builds a Box2D v3.1 world from the
 * plan through v3.1's own calls alone) against the v3.1 adapter: the same scene gives the
 * same world, body for body and bit for bit, before the first step and after 600.
 */
#define PORT_V31_NO_MAIN
#include "../examples/port_v31.c"

#include <box2scene/box2d3.h>

#include "fidelity_scenes.h"
#include "test_macros.h"

#define SAME_BITS(a, b) (memcmp(&(a), &(b), sizeof(a)) == 0)

/* Every body of both worlds in the same state, to the bit. */
static int bodies_agree(const port_world* port, const b2s_box2d3_built* built) {
    ENSURE_EQ(port->body_count, built->body_count);
    for (uint32_t i = 0; i < port->body_count; ++i) {
        b2BodyId a = port->bodies[i], b = built->bodies[i];
        ENSURE_EQ(B2_IS_NULL(a), B2_IS_NULL(b));
        if (B2_IS_NULL(a)) {
            continue;
        }
        b2Vec2 pa = b2Body_GetPosition(a), pb = b2Body_GetPosition(b);
        b2Rot qa = b2Body_GetRotation(a), qb = b2Body_GetRotation(b);
        b2Vec2 va = b2Body_GetLinearVelocity(a), vb = b2Body_GetLinearVelocity(b);
        float wa = b2Body_GetAngularVelocity(a), wb = b2Body_GetAngularVelocity(b);
        b2MassData ma = b2Body_GetMassData(a), mb = b2Body_GetMassData(b);
        ENSURE(SAME_BITS(pa, pb));
        ENSURE(SAME_BITS(qa, qb));
        ENSURE(SAME_BITS(va, vb));
        ENSURE(SAME_BITS(wa, wb));
        ENSURE(SAME_BITS(ma, mb));
        ENSURE_EQ(b2Body_GetShapeCount(a), b2Body_GetShapeCount(b));
        ENSURE_EQ(b2Body_GetJointCount(a), b2Body_GetJointCount(b));
    }
    return 0;
}

/* How many bodies stand elsewhere than they started. */
static uint32_t bodies_moved(const port_world* port, const b2Vec2* start) {
    uint32_t moved = 0;
    for (uint32_t i = 0; i < port->body_count; ++i) {
        if (B2_IS_NON_NULL(port->bodies[i])) {
            b2Vec2 p = b2Body_GetPosition(port->bodies[i]);
            moved += p.x != start[i].x || p.y != start[i].y;
        }
    }
    return moved;
}

/* `scene` built by the port and by the adapter, compared, stepped 600 times, compared
 * again. Returns 0 when they agree throughout; `moved` counts the bodies the steps moved. */
static int port_equals_adapter(const b2s_scene* scene, uint32_t* moved) {
    port_world port = {0};
    ENSURE(port_build(scene, &port));
    b2WorldDef def = b2s_box2d3_world_def(scene, (b2Vec2){0.0f, -10.0f});
    b2WorldId world = b2CreateWorld(&def);
    b2s_box2d3_built* built = b2s_box2d3_build_world(scene, world);
    ENSURE(built != NULL);
    b2Counters a = b2World_GetCounters(port.world), b = b2World_GetCounters(world);
    ENSURE_EQ(a.bodyCount, b.bodyCount);
    ENSURE_EQ(a.shapeCount, b.shapeCount);
    ENSURE_EQ(a.jointCount, b.jointCount);
    ENSURE_EQ(a.jointCount, port.joint_count);
    ENSURE_EQ(port.report_count, built->reports.count);
    ENSURE(bodies_agree(&port, built) == 0);
    b2Vec2* start = calloc(port.body_count + 1, sizeof *start);
    ENSURE(start != NULL);
    for (uint32_t i = 0; i < port.body_count; ++i) {
        if (B2_IS_NON_NULL(port.bodies[i])) {
            start[i] = b2Body_GetPosition(port.bodies[i]);
        }
    }
    for (int step = 0; step < 600; ++step) {
        b2World_Step(port.world, 1.0f / 60.0f, 4);
        b2World_Step(world, 1.0f / 60.0f, 4);
    }
    int failed = bodies_agree(&port, built);
    *moved = bodies_moved(&port, start);
    free(start);
    b2s_box2d3_built_free(built);
    b2DestroyWorld(world);
    port_free(&port);
    return failed;
}

static int the_showcase_builds_as_the_adapter_builds_it(void) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/scenes/showcase.xml", BOX2SCENE_SOURCE_DIR);
    b2s_scene* scene = NULL;
    ENSURE_EQ(b2s_load_file(path, NULL, &scene, NULL), B2S_CODE_OK);
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    /* Every body of the file is made; every joint but the pulley and the gear (v3 has
     * neither). */
    port_world port = {0};
    ENSURE(port_build(scene, &port));
    b2Counters counters = b2World_GetCounters(port.world);
    ENSURE_EQ(counters.bodyCount, view->body_count);
    ENSURE_EQ(counters.jointCount, view->joint_count - 2);
    port_free(&port);
    uint32_t moved = 0;
    int failed = port_equals_adapter(scene, &moved);
    b2s_scene_free(scene);
    ENSURE_EQ(failed, 0);
    ENSURE(moved > 0);
    return 0;
}

/* The reference scenes: every shape kind (chains, loops, one-sided edges) and every joint
 * kind v3.1 holds (rope, wheel, line, motor, friction), mass data and body flags. */
static int every_reference_scene_builds_as_the_adapter_builds_it(void) {
    uint32_t moved = 0;
    for (size_t i = 0; i < FIDELITY_SCENE_COUNT; ++i) {
        const char* xml = fidelity_scenes[i].xml;
        b2s_scene* scene = NULL;
        ENSURE_EQ(b2s_load_memory((const uint8_t*)xml, strlen(xml), NULL, &scene, NULL),
                  B2S_CODE_OK);
        uint32_t scene_moved = 0;
        int failed = port_equals_adapter(scene, &scene_moved);
        b2s_scene_free(scene);
        if (failed != 0) {
            fprintf(stderr, "scene %s differs\n", fidelity_scenes[i].name);
            return 1;
        }
        moved += scene_moved;
    }
    ENSURE(moved > 0);
    return 0;
}

/* A spinning body of shapes off its origin: its centre's velocity must gain the spin's
 * share once, from the origin to the centre of all its shapes, as the plan predicts it; a
 * mass updated after each shape adds it in steps, and rounds otherwise. */
static int a_spinning_body_of_many_shapes_builds_as_the_adapter_builds_it(void) {
    static const char xml[] =
        "<World Version=\"2\"><Gravity>0 0</Gravity><Shapes>"
        "<Shape Type=\"Circle\"><Radius>0.3</Radius><Position>1.1 0.3</Position></Shape>"
        "<Shape Type=\"Circle\"><Radius>0.7</Radius><Position>2.7 -1.3</Position></Shape>"
        "<Shape Type=\"Circle\"><Radius>0.45</Radius><Position>-0.4 1.9</Position></Shape>"
        "</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>1.3</Density></Fixture>"
        "<Fixture><Shape>1</Shape><Density>2.5</Density></Fixture>"
        "<Fixture><Shape>2</Shape><Density>0.7</Density></Fixture></Fixtures><Bodies>"
        "<Body Type=\"Dynamic\"><Position>0.3 0.2</Position><Angle>0.7</Angle>"
        "<LinearVelocity>0.1 -0.3</LinearVelocity><AngularVelocity>3.3</AngularVelocity>"
        "<Fixtures><ID>0</ID><ID>1</ID><ID>2</ID></Fixtures></Body></Bodies></World>";
    b2s_scene* scene = NULL;
    ENSURE_EQ(b2s_load_memory((const uint8_t*)xml, sizeof xml - 1, NULL, &scene, NULL),
              B2S_CODE_OK);
    uint32_t moved = 0;
    int failed = port_equals_adapter(scene, &moved);
    b2s_scene_free(scene);
    ENSURE_EQ(failed, 0);
    ENSURE_EQ(moved, 1);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(the_showcase_builds_as_the_adapter_builds_it);
    failed += RUN_TEST(every_reference_scene_builds_as_the_adapter_builds_it);
    failed += RUN_TEST(a_spinning_body_of_many_shapes_builds_as_the_adapter_builds_it);
    return failed;
}
