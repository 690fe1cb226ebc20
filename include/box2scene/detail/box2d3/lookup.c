/*
 * Lookups: the engine object built from a named scene record, and the record an engine
 * object was built from. A built result is indexed like the scene's arrays, so both ways
 * are a walk over one array: the name is the scene's (b2s_scene_find_*), the object is the
 * result's. What a fixture slot holds differs by version (v31.h, v32.h: b2s3_slot_shape,
 * b2s3_slot_holds).
 */

/* The scene and the result agree on this many records of a kind, or 0. */
static uint32_t b2s3_common_count(uint32_t scene_count, uint32_t built_count) {
    return scene_count == built_count ? built_count : 0u;
}

b2BodyId B2S3_API(find_body)(const b2s3_built_t* built, const b2s_scene* scene,
                             const char* name) {
    const b2s_scene_view* view = scene != NULL ? b2s_scene_get_view(scene) : NULL;
    if (built == NULL || view == NULL) {
        return b2_nullBodyId;
    }
    uint32_t index = b2s_scene_find_body(scene, name);
    return index < b2s3_common_count(view->body_count, built->body_count) ? built->bodies[index]
                                                                           : b2_nullBodyId;
}

b2ShapeId B2S3_API(find_fixture)(const b2s3_built_t* built, const b2s_scene* scene,
                                 const char* name) {
    const b2s_scene_view* view = scene != NULL ? b2s_scene_get_view(scene) : NULL;
    if (built == NULL || view == NULL) {
        return b2_nullShapeId;
    }
    uint32_t fixture = b2s_scene_find_fixture(scene, name);
    uint32_t slots = b2s3_common_count(view->fixture_id_count, built->fixture_count);
    for (uint32_t slot = 0; fixture != B2S_NONE && slot < slots; ++slot) {
        if (view->fixture_ids[slot] == fixture) {
            return b2s3_slot_shape(built, slot);
        }
    }
    return b2_nullShapeId;
}

b2JointId B2S3_API(find_joint)(const b2s3_built_t* built, const b2s_scene* scene,
                               const char* name) {
    const b2s_scene_view* view = scene != NULL ? b2s_scene_get_view(scene) : NULL;
    if (built == NULL || view == NULL) {
        return b2_nullJointId;
    }
    uint32_t index = b2s_scene_find_joint(scene, name);
    return index < b2s3_common_count(view->joint_count, built->joint_count)
               ? built->joints[index]
               : b2_nullJointId;
}

uint32_t B2S3_API(body_index)(const b2s3_built_t* built, b2BodyId body) {
    if (built == NULL || !b2Body_IsValid(body)) {
        return B2S_NONE;
    }
    for (uint32_t i = 0; i < built->body_count; ++i) {
        if (B2_ID_EQUALS(built->bodies[i], body)) {
            return i;
        }
    }
    return B2S_NONE;
}

uint32_t B2S3_API(shape_slot)(const b2s3_built_t* built, b2ShapeId shape) {
    if (built == NULL || !b2Shape_IsValid(shape)) {
        return B2S_NONE;
    }
    for (uint32_t slot = 0; slot < built->fixture_count; ++slot) {
        if (b2s3_slot_holds(built, slot, shape)) {
            return slot;
        }
    }
    return B2S_NONE;
}

uint32_t B2S3_API(joint_index)(const b2s3_built_t* built, b2JointId joint) {
    if (built == NULL || !b2Joint_IsValid(joint)) {
        return B2S_NONE;
    }
    for (uint32_t i = 0; i < built->joint_count; ++i) {
        if (B2_ID_EQUALS(built->joints[i], joint)) {
            return i;
        }
    }
    return B2S_NONE;
}
