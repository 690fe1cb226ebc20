/*
 * Bodies: the body def (placed), its fixtures, and its mass: predicted bit for bit before
 * the body is made, so that the working range can be checked first, then given.
 */

static bool b2s3_mass_data_given(const b2s_mass_data* given) {
    return given->mass_given || given->center_given || given->inertia_given;
}

static b2MassData b2s3_geometry_mass(const b2s3_geometry* g, float density) {
    b2MassData none = {0.0f, {0.0f, 0.0f}, 0.0f};
    switch (g->kind) {
    case B2S3_CIRCLE: return b2ComputeCircleMass(&g->circle, density);
    case B2S3_POLYGON: return b2ComputePolygonMass(&g->polygon, density);
    default: return none;
    }
}

/* Box2D 2.x, which the format's files were made for, gives a dynamic body without mass
 * 1 kg; v3 would leave it at 0, unmoved by gravity. */
static float b2s3_positive(float mass) {
    return mass > 0.0f ? mass : 1.0f;
}

/* A dynamic body's final mass data, as Box2D 2.x's SetMassData makes it: from its shapes,
 * then what its MassData gives, a mass of 0 counted as 1 kg. The file's inertia is about
 * the body origin, v3's about the centre of mass; a rotation that is fixed has none. */
static b2MassData b2s3_final_mass(b2MassData computed, const b2s_body* body) {
    const b2s_mass_data* given = &body->mass_data;
    b2MassData out = computed;
    out.mass = b2s3_positive(computed.mass);
    if (!b2s3_mass_data_given(given)) {
        return out;
    }
    float origin_inertia =
        computed.rotationalInertia + computed.mass * b2Dot(computed.center, computed.center);
    if (given->mass_given) {
        out.mass = b2s3_positive(given->mass);
    }
    if (given->center_given) {
        out.center = b2s3_to_b2(given->center);
    }
    if (given->inertia_given) {
        origin_inertia = given->inertia;
    }
    out.rotationalInertia = body->fixed_rotation || !(origin_inertia > 0.0f)
                                ? 0.0f
                                : origin_inertia - out.mass * b2Dot(out.center, out.center);
    return out;
}

/* The mass data the adapter gives a dynamic body, or false when memory runs out; `check`
 * fails when v3 would assert or the result lies beyond the working range. */
static bool b2s3_predicted_mass(const b2s3_builder* b, const b2s_body* body, b2s3_check* check,
                                b2MassData* out) {
    size_t capacity = body->fixtures.count > 0 ? body->fixtures.count : 1;
    b2MassData* masses = (b2MassData*)malloc(capacity * sizeof(b2MassData));
    float* densities = (float*)malloc(capacity * sizeof(float));
    if (masses == NULL || densities == NULL) {
        free(masses);
        free(densities);
        return false;
    }
    size_t created = 0;
    uint64_t end = (uint64_t)body->fixtures.first + body->fixtures.count;
    for (uint64_t slot = body->fixtures.first; slot < end && slot < b->view->fixture_id_count;
         ++slot) {
        uint32_t index = b->view->fixture_ids[slot];
        if (!b2s3_fixture_creatable(b, index)) {
            continue;
        }
        const b2s_fixture* fixture = &b->view->fixtures[index];
        densities[created] = fixture->density;
        masses[created] = b2s3_geometry_mass(&b->geometries[fixture->shape], fixture->density);
        created += 1;
    }
    bool inertia_kept = true;
    b2MassData computed =
        b2s3_mass_from_shapes(masses, densities, created, body->fixed_rotation, &inertia_kept);
    free(masses);
    free(densities);
    if (!inertia_kept) {
        b2s3_fail(check, "its shapes leave no positive inertia about its centre of mass in "
                         B2S3_ENGINE "'s float arithmetic (which asserts)");
    }
    b2s3_vector(check, "its centre of mass", b2s3_to_b2s(computed.center),
                b2s3_range()->max_length, "m");
    b2MassData final_mass = b2s3_final_mass(computed, body);
    b2s3_zero_or_within(check, "its mass", final_mass.mass, b2s3_range()->min_mass,
                        b2s3_range()->max_mass, "kg");
    b2s3_vector(check, "its centre of mass", b2s3_to_b2s(final_mass.center),
                b2s3_range()->max_length, "m");
    if (final_mass.rotationalInertia < 0.0f) {
        b2s3_fail(check, "its MassData leaves a negative inertia about the centre of mass "
                         "(Inertia < Mass * |Center|^2), which " B2S3_ENGINE " asserts against");
    }
    b2s3_zero_or_within(check, "its inertia about the centre of mass",
                        final_mass.rotationalInertia, b2s3_range()->min_inertia,
                        b2s3_range()->max_inertia, "kg m^2");
    *out = final_mass;
    return true;
}

static b2s3_check b2s3_body_check(const b2s3_builder* b, const b2s_body* body) {
    b2s3_check check = {{0}};
    b2s3_vector(&check, "Position", body->position, b2s3_range()->max_length, "m");
    b2s3_magnitude(&check, "Angle", body->angle, b2s3_range()->max_angle, "rad");
    if (body->kind != B2S_BODY_KIND_STATIC) {
        b2s3_vector(&check, "LinearVelocity", body->linear_velocity, b2s3_range()->max_speed,
                    "m/s");
        b2s3_magnitude(&check, "AngularVelocity", body->angular_velocity, b2s3_range()->max_speed,
                       "rad/s");
        float limit = b2World_GetMaximumLinearSpeed(b->world);
        float speed = b2Length(b2s3_to_b2(body->linear_velocity));
        if (b2s3_passed(&check) && !(speed <= limit)) {
            b2s3_fail(&check,
                      "LinearVelocity (%.9g, %.9g) is faster than the world's maximum linear "
                      "speed %g m/s, to which " B2S3_ENGINE " would clamp it",
                      (double)body->linear_velocity.x, (double)body->linear_velocity.y,
                      (double)limit);
        }
    }
    b2s3_magnitude(&check, "LinearDamping", body->linear_damping, b2s3_range()->max_damping, "1/s");
    b2s3_magnitude(&check, "AngularDamping", body->angular_damping, b2s3_range()->max_damping,
                   "1/s");
    b2s3_magnitude(&check, "GravityScale", body->gravity_scale, b2s3_range()->max_gravity_scale, "");
    if (body->kind == B2S_BODY_KIND_DYNAMIC && b2s3_passed(&check)) {
        b2Vec2 gravity = b2MulSV(body->gravity_scale, b2World_GetGravity(b->world));
        b2s3_vector(&check, "GravityScale times the world's gravity", b2s3_to_b2s(gravity),
                    b2s3_range()->max_acceleration, "m/s^2");
    }
    if (body->mass_data.center_given) {
        b2s3_vector(&check, "MassData Center", body->mass_data.center, b2s3_range()->max_length,
                    "m");
    }
    if (b2s3_passed(&check)) {
        b2Vec2 placed = b2TransformPoint(b->placement, b2s3_to_b2(body->position));
        b2s3_vector(&check, "its placed Position", b2s3_to_b2s(placed), b2s3_range()->max_length,
                    "m");
    }
    return check;
}

/* The fixtures of a body that was not created: they depend on it. */
static void b2s3_skip_fixtures_of(b2s3_builder* b, uint32_t body_index, const b2s_body* body) {
    uint64_t end = (uint64_t)body->fixtures.first + body->fixtures.count;
    for (uint64_t slot = body->fixtures.first; slot < end && slot < b->view->fixture_id_count;
         ++slot) {
        uint32_t index = b->view->fixture_ids[slot];
        B2S3_REPORT(b, B2S_CODE_SKIPPED_DEPENDENT, "fixture", index,
                    index < b->view->fixture_count ? b->view->fixtures[index].name : NULL,
                    "fixture %u of body %u: the body was not created; fixture skipped",
                    (unsigned)index, (unsigned)body_index);
    }
}

/* v3 asserts against a negative damping, which the format does not forbid. */
static float b2s3_damping(b2s3_builder* b, uint32_t index, const b2s_body* body, float value,
                          const char* field) {
    if (value >= 0.0f) {
        return value;
    }
    B2S3_REPORT(b, B2S_CODE_NEGATIVE_VALUE, "body", index, body->name,
                "%s %.9g is negative, which " B2S3_ENGINE " does not allow; 0 was used", field,
                (double)value);
    return 0.0f;
}

/* The linear velocity of a body's origin, placed. */
static b2Vec2 b2s3_origin_velocity_placed(const b2s3_builder* b, const b2s_body* body) {
    return b2RotateVector(b->placement.q, b2s3_to_b2(body->linear_velocity));
}

static b2BodyDef b2s3_body_def(b2s3_builder* b, uint32_t index, const b2s_body* body) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = (b2BodyType)body->kind;
    /* b2MakeRot approximates; the rotation of the file's angle is its cosine and sine. */
    b2Rot rotation = {cosf(body->angle), sinf(body->angle)};
    b2s3_set_pose(&def, b2TransformPoint(b->placement, b2s3_to_b2(body->position)),
                  b2MulRot(b->placement.q, rotation));
    if (body->kind != B2S_BODY_KIND_STATIC) {
        def.linearVelocity = b2s3_origin_velocity_placed(b, body);
        /* A body whose rotation is fixed keeps turning at the rate it starts with in 2.x and
         * v3.1 (no torque or impulse changes it); v3.2's lock stops it (reported). */
        def.angularVelocity = body->angular_velocity;
    }
    def.linearDamping = b2s3_damping(b, index, body, body->linear_damping, "LinearDamping");
    def.angularDamping = b2s3_damping(b, index, body, body->angular_damping, "AngularDamping");
    def.gravityScale = body->gravity_scale;
    def.enableSleep = body->allow_sleep;
    def.isAwake = body->awake;
    b2s3_lock_rotation(&def, body->fixed_rotation);
    def.isBullet = body->bullet;
    def.isEnabled = body->active;
    /* A name longer than v3 keeps is not cut (that could split a character). */
    if (body->name != NULL && strlen(body->name) <= B2S3_NAME_LENGTH) {
        def.name = body->name;
    }
    return def;
}

/* What a body's def cannot say of the file, reported. */
static void b2s3_report_body_losses(b2s3_builder* b, uint32_t index, const b2s_body* body) {
    if (fabsf(body->angle) > B2_PI) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_CAPTURE, "body", index, body->name,
                    B2S3_ENGINE " keeps a rotation, not an angle: the whole turns of Angle "
                    "%.9g are lost, and a capture writes it within +-pi",
                    (double)body->angle);
    }
    if (body->name != NULL && strlen(body->name) > B2S3_NAME_LENGTH) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_BODY, "body", index, body->name,
                    "its Name is longer than the %u bytes " B2S3_ENGINE " keeps of a name; "
                    "the body has none, and a capture writes none",
                    (unsigned)B2S3_NAME_LENGTH);
    }
    if (B2S3_LOCK_STOPS_SPIN && body->fixed_rotation && body->kind != B2S_BODY_KIND_STATIC &&
        body->angular_velocity != 0.0f) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_BODY, "body", index, body->name,
                    "FixedRotation with AngularVelocity %.9g rad/s: " B2S3_ENGINE "'s motion "
                    "lock stops the spin at the first step, where Box2D 2.x and v3.1 keep the "
                    "body turning at that rate",
                    (double)body->angular_velocity);
    }
    if (!body->awake && !body->allow_sleep && body->kind != B2S_BODY_KIND_STATIC) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_BODY, "body", index, body->name,
                    "Awake false with AllowSleep false: " B2S3_ENGINE " creates such a body "
                    "awake (Box2D 2.x keeps it asleep until it is touched)");
    }
}

/* The mass the body gets, given after v3 has computed its own (which clears the mark v3
 * asserts against at the step) where it differs: MassData, a fixed rotation, no mass. 2.x's
 * SetMassData keeps the origin's velocity when the centre moves; v3's does not, so the
 * velocity is given again, as v3 computes it from the origin's. */
static void b2s3_give_mass(b2s3_builder* b, const b2s_body* body, b2BodyId created,
                           b2MassData mass) {
    b2MassData applied = b2Body_GetMassData(created);
    if (!b2s3_mass_data_given(&body->mass_data) && !body->fixed_rotation &&
        applied.mass > 0.0f) {
        return;
    }
    b2Body_SetMassData(created, mass);
    if (!b2Body_IsAwake(created) || !b2Body_IsEnabled(created)) {
        return;
    }
    b2Transform transform = b2Body_GetTransform(created);
    b2Vec2 center = b2TransformPoint(transform, mass.center);
    float w = b2Body_GetAngularVelocity(created);
    b2Vec2 v = b2Add(b2s3_origin_velocity_placed(b, body),
                     b2CrossSV(w, b2Sub(center, transform.p)));
    b2Body_SetLinearVelocity(created, v);
}

static void b2s3_make_body(b2s3_builder* b, uint32_t index) {
    const b2s_body* body = &b->view->bodies[index];
    if (body->kind > B2S_BODY_KIND_DYNAMIC) {
        B2S3_REPORT(b, B2S_CODE_UNKNOWN_TYPE, "body", index, body->name,
                    "unknown body kind %u; body skipped", (unsigned)body->kind);
        b2s3_skip_fixtures_of(b, index, body);
        return;
    }
    uint64_t end = (uint64_t)body->fixtures.first + body->fixtures.count;
    if (end > b->view->fixture_id_count) {
        B2S3_REPORT(b, B2S_CODE_ID_OUT_OF_RANGE, "body", index, body->name,
                    "its fixture list lies outside the scene's fixture ID pool; body skipped");
        return;
    }
    b2s3_check check = b2s3_body_check(b, body);
    b2MassData mass = {0.0f, {0.0f, 0.0f}, 0.0f};
    if (body->kind == B2S_BODY_KIND_DYNAMIC && b2s3_passed(&check) &&
        !b2s3_predicted_mass(b, body, &check, &mass)) {
        b->list.out_of_memory = true;
        return;
    }
    if (!b2s3_passed(&check)) {
        b2s3_beyond(b, &check, "body", index, body->name, "");
        b2s3_skip_fixtures_of(b, index, body);
        return;
    }
    b2s3_report_body_losses(b, index, body);
    b2BodyDef def = b2s3_body_def(b, index, body);
    b2BodyId created = b2CreateBody(b->world, &def);
    b->built->bodies[index] = created;
    for (uint32_t slot = body->fixtures.first; slot < end; ++slot) {
        b2s3_make_fixture(b, index, slot, created);
    }
    if (b2s3_needs_mass_update(def.type)) {
        b2Body_ApplyMassFromShapes(created);
    }
    if (body->kind == B2S_BODY_KIND_DYNAMIC) {
        b2s3_give_mass(b, body, created, mass);
        b->masses[index] = mass;
    }
}
