/*
 * Bodies: the body def the plan gives (placed), its shapes, then the mass: computed by v3
 * from the shapes where the plan says so, then given where the plan gives one (with the
 * velocity v3's b2Body_SetMassData does not keep).
 */

static b2BodyDef b2s3_body_def(const b2s_plan_body* body) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = (b2BodyType)body->kind;
    b2Rot rotation = {body->rotation.c, body->rotation.s};
    b2s3_set_pose(&def, b2s3_to_b2(body->position), rotation);
    def.linearVelocity = b2s3_to_b2(body->linear_velocity);
    def.angularVelocity = body->angular_velocity;
    def.linearDamping = body->linear_damping;
    def.angularDamping = body->angular_damping;
    def.gravityScale = body->gravity_scale;
    def.enableSleep = body->allow_sleep;
    def.isAwake = body->awake;
    b2s3_lock_rotation(&def, body->fixed_rotation);
    def.isBullet = body->bullet;
    def.isEnabled = body->enabled;
    def.name = body->name;
    return def;
}

static void b2s3_make_body(b2s3_builder* b, const b2s_plan_body* body) {
    b2BodyDef def = b2s3_body_def(body);
    b2BodyId created = b2CreateBody(b->world, &def);
    b->built->bodies[body->body] = created;
    uint32_t end = body->shapes.first + body->shapes.count;
    for (uint32_t i = body->shapes.first; i < end && !b->list.out_of_memory; ++i) {
        b2s3_make_shape(b, &b->plan->shapes[i], created);
    }
    if (body->apply_mass_from_shapes) {
        b2Body_ApplyMassFromShapes(created);
    }
    if (body->set_mass) {
        b2MassData mass = {body->mass.mass, b2s3_to_b2(body->mass.center), body->mass.inertia};
        b2Body_SetMassData(created, mass);
    }
    if (body->set_velocity) {
        b2Body_SetLinearVelocity(created, b2s3_to_b2(body->velocity_after_mass));
    }
}
