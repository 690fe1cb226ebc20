/*
 * The v3 adapters' lookups: the engine id of a named body, fixture or joint in one call (the
 * null id where none was made), and the scene record a body, shape (a chain's segments
 * included) or joint came from. Compiled once per v3 adapter as box2d3_lookup_test and
 * box2d32_lookup_test.
 */
#include V3_SUPPORT

/* A fixture two bodies share, an open chain, and a pulley, which v3 has not: skipped. */
static const char* const level =
    "<World Version=\"2\">"
    "<Shapes>"
    "<Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 -0.5</Vertex><Vertex>0.5 -0.5</Vertex>"
    "<Vertex>0.5 0.5</Vertex><Vertex>-0.5 0.5</Vertex></Vertices></Shape>"
    "<Shape Type=\"Chain\"><Vertices><Vertex>-5 0</Vertex><Vertex>0 0</Vertex>"
    "<Vertex>5 0</Vertex></Vertices><PrevVertex>-6 1</PrevVertex>"
    "<HasPrevVertex>true</HasPrevVertex><NextVertex>6 1</NextVertex>"
    "<HasNextVertex>true</HasNextVertex></Shape>"
    "<Shape Type=\"Circle\"><Radius>0.4</Radius><Position>0 0</Position></Shape>"
    "</Shapes>"
    "<Fixtures>"
    "<Fixture><Name>Track</Name><Shape>1</Shape></Fixture>"
    "<Fixture><Name>CrateSkin</Name><Shape>0</Shape><Density>1</Density></Fixture>"
    "<Fixture><Name>Tyre</Name><Shape>2</Shape><Density>1</Density></Fixture>"
    "</Fixtures>"
    "<Bodies>"
    "<Body Type=\"Static\"><Name>Ground</Name><Fixtures><ID>0</ID></Fixtures></Body>"
    "<Body Type=\"Dynamic\"><Name>CrateA</Name><Position>-2 1</Position>"
    "<Fixtures><ID>1</ID></Fixtures></Body>"
    "<Body Type=\"Dynamic\"><Name>CrateB</Name><Position>2 1</Position>"
    "<Fixtures><ID>1</ID></Fixtures></Body>"
    "<Body Type=\"Dynamic\"><Name>Wheel</Name><Position>0 3</Position>"
    "<Fixtures><ID>2</ID></Fixtures></Body>"
    "</Bodies>"
    "<Joints>"
    "<Joint Type=\"Revolute\"><Name>Hinge</Name><BodyA>1</BodyA><BodyB>2</BodyB>"
    "<LocalAnchorA>2 0</LocalAnchorA><LocalAnchorB>-2 0</LocalAnchorB></Joint>"
    "<Joint Type=\"Pulley\"><Name>Rope</Name><BodyA>1</BodyA><BodyB>3</BodyB>"
    "<GroundAnchorA>-2 6</GroundAnchorA><GroundAnchorB>0 6</GroundAnchorB>"
    "<LocalAnchorA>0 0</LocalAnchorA><LocalAnchorB>0 0</LocalAnchorB>"
    "<LengthA>5</LengthA><LengthB>3</LengthB><Ratio>1</Ratio></Joint>"
    "</Joints>"
    "</World>";

static bool same_body(b2BodyId a, b2BodyId b) {
    return B2_ID_EQUALS(a, b);
}

static bool same_shape(b2ShapeId a, b2ShapeId b) {
    return B2_ID_EQUALS(a, b);
}

static int named_records_reach_their_engine_ids(void) {
    b2s_scene* scene = load_text(level);
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    const v3_built* built = world.built;
    ENSURE(built->joint_count == 2 && B2_IS_NULL(built->joints[1])); /* skipped, reported */

    ENSURE(B2_IS_NON_NULL(built->bodies[2]));
    ENSURE(same_body(V3_ADAPTER(find_body)(built, scene, "CrateB"), built->bodies[2]));
    ENSURE(same_body(V3_ADAPTER(find_body)(built, scene, "Wheel"), built->bodies[3]));
    /* CrateSkin serves CrateA and CrateB: the first body's, entry 1 of the pool. */
    b2ShapeId skin = V3_ADAPTER(find_fixture)(built, scene, "CrateSkin");
    ENSURE(B2_IS_NON_NULL(skin) && same_shape(skin, built->shapes[1]));
    ENSURE(same_body(b2Shape_GetBody(skin), built->bodies[1]));
    /* A chain is found by its first segment. */
    b2ShapeId track = V3_ADAPTER(find_fixture)(built, scene, "Track");
    ENSURE(B2_IS_NON_NULL(track) && b2Shape_GetType(track) == b2_chainSegmentShape);
    b2ShapeId segments[2];
    ENSURE_EQ(v3_chain_segments(built, 0, segments, 2), 2);
    ENSURE(same_shape(track, segments[0]));
    b2JointId hinge = V3_ADAPTER(find_joint)(built, scene, "Hinge");
    ENSURE(B2_IS_NON_NULL(hinge) && B2_ID_EQUALS(hinge, built->joints[0]));
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

static int what_was_not_made_or_not_named_is_null(void) {
    b2s_scene* scene = load_text(level);
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    const v3_built* built = world.built;
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_joint)(built, scene, "Rope")));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_body)(built, scene, "Nobody")));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_fixture)(built, scene, "Nothing")));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_joint)(built, scene, NULL)));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_body)(built, NULL, "CrateA")));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_body)(NULL, scene, "CrateA")));
    /* A result of another scene, with other counts, finds nothing rather than a stranger. */
    b2s_scene* other = load_text("<World Version=\"2\"><Bodies><Body Type=\"Static\"/></Bodies>"
                                 "</World>");
    ENSURE(other != NULL);
    v3_built* other_built = V3_ADAPTER(build_world)(other, world.id);
    ENSURE(other_built != NULL);
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_body)(other_built, scene, "Ground")));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_fixture)(other_built, scene, "Track")));
    ENSURE(B2_IS_NULL(V3_ADAPTER(find_joint)(other_built, scene, "Hinge")));
    V3_ADAPTER(built_free)(other_built);
    b2s_scene_free(other);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

static int engine_ids_name_their_scene_records(void) {
    b2s_scene* scene = load_text(level);
    ENSURE(scene != NULL);
    v3_world world = build_v3(scene);
    const v3_built* built = world.built;
    const b2s_scene_view* view = b2s_scene_get_view(scene);
    for (uint32_t i = 0; i < view->body_count; ++i) {
        ENSURE_EQ(V3_ADAPTER(body_index)(built, built->bodies[i]), i);
    }
    /* Each body's copy of the shared fixture names its own entry, both the one fixture. */
    b2ShapeId on_b;
    ENSURE_EQ(b2Body_GetShapes(built->bodies[2], &on_b, 1), 1);
    uint32_t b_slot = V3_ADAPTER(shape_slot)(built, on_b);
    ENSURE_EQ(b_slot, 2);
    ENSURE_EQ(view->fixture_ids[b_slot], 1);
    /* Every segment of the chain names the chain's entry. */
    b2ShapeId segments[2];
    ENSURE_EQ(v3_chain_segments(built, 0, segments, 2), 2);
    ENSURE_EQ(V3_ADAPTER(shape_slot)(built, segments[0]), 0);
    ENSURE_EQ(V3_ADAPTER(shape_slot)(built, segments[1]), 0);
    ENSURE_EQ(V3_ADAPTER(joint_index)(built, built->joints[0]), 0);
    /* What the host made itself, a destroyed shape and the null ids came from no record. */
    b2BodyDef def = b2DefaultBodyDef();
    def.type = b2_dynamicBody;
    b2BodyId own = b2CreateBody(world.id, &def);
    b2ShapeDef shape_def = b2DefaultShapeDef();
    b2Circle dot = {{0.0f, 0.0f}, 0.1f};
    b2ShapeId own_shape = b2CreateCircleShape(own, &shape_def, &dot);
    b2RevoluteJointDef hinge = v3_revolute_def(own, built->bodies[3], b2Vec2_zero, b2Vec2_zero);
    b2JointId own_joint = b2CreateRevoluteJoint(world.id, &hinge);
    ENSURE_EQ(V3_ADAPTER(body_index)(built, own), B2S_NONE);
    ENSURE_EQ(V3_ADAPTER(shape_slot)(built, own_shape), B2S_NONE);
    ENSURE_EQ(V3_ADAPTER(joint_index)(built, own_joint), B2S_NONE);
    b2ShapeId tyre;
    ENSURE_EQ(b2Body_GetShapes(built->bodies[3], &tyre, 1), 1);
    ENSURE_EQ(V3_ADAPTER(shape_slot)(built, tyre), 3);
    b2DestroyShape(tyre, true);
    ENSURE_EQ(V3_ADAPTER(shape_slot)(built, tyre), B2S_NONE);
    ENSURE_EQ(V3_ADAPTER(body_index)(built, b2_nullBodyId), B2S_NONE);
    ENSURE_EQ(V3_ADAPTER(shape_slot)(built, b2_nullShapeId), B2S_NONE);
    ENSURE_EQ(V3_ADAPTER(joint_index)(NULL, built->joints[0]), B2S_NONE);
    free_v3(&world);
    b2s_scene_free(scene);
    return 0;
}

int main(void) {
    int failed = 0;
    failed += RUN_TEST(named_records_reach_their_engine_ids);
    failed += RUN_TEST(what_was_not_made_or_not_named_is_null);
    failed += RUN_TEST(engine_ids_name_their_scene_records);
    return failed;
}
