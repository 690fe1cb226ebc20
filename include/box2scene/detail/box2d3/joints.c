/*
 * Joints: checked against the working range once every body has its final mass, then made
 * through the version's frames (v32.h) from the scene's anchors, axis and reference angle.
 */

static b2BodyId b2s3_created_body(const b2s3_builder* b, uint32_t index) {
    return index < b->built->body_count ? b->built->bodies[index] : b2_nullBodyId;
}

static bool b2s3_is_dynamic(const b2s3_builder* b, uint32_t body) {
    return b2Body_GetType(b->built->bodies[body]) == b2_dynamicBody;
}

/* Box2D's joint solvers work with 1/m + r^2/I of each body at the anchor (r from its centre
 * of mass) and invert 2x2 matrices of such terms: past this, their products overflow or the
 * determinant loses every bit. */
static void b2s3_check_anchor(const b2s3_builder* b, b2s3_check* check, const char* field,
                              uint32_t body, b2Vec2 anchor, float lever) {
    if (!b2s3_is_dynamic(b, body)) {
        return;
    }
    const b2MassData* mass = &b->masses[body];
    float r = b2Distance(anchor, mass->center);
    float inertia = mass->rotationalInertia;
    float compliance = 1.0f / mass->mass + (inertia > 0.0f ? r * r / inertia : 0.0f);
    if (!(compliance <= b2s3_range()->max_compliance)) {
        b2s3_fail(check,
                  "%s: the joint acts %.9g m from the centre of mass of body %u (mass %.9g kg, "
                  "inertia %.9g kg m^2), where 1/m + r^2/I = %g 1/kg lies beyond " B2S3_ENGINE
                  "'s working range (at most %g 1/kg)",
                  field, (double)r, (unsigned)body, (double)mass->mass, (double)inertia,
                  (double)compliance, (double)b2s3_range()->max_compliance);
    } else if (inertia > 0.0f && !(r <= lever * sqrtf(inertia / mass->mass))) {
        b2s3_fail(check,
                  "%s: the joint acts %g radii of gyration from the centre of mass of body %u, "
                  "beyond " B2S3_ENGINE "'s working range (at most %g)",
                  field, (double)(r / sqrtf(inertia / mass->mass)), (unsigned)body,
                  (double)lever);
    }
}

/* sqrt(I/m) about the centre of mass; a body that cannot turn has no bound of its own. */
static float b2s3_gyration(const b2MassData* mass) {
    return mass->rotationalInertia > 0.0f ? sqrtf(mass->rotationalInertia / mass->mass) : FLT_MAX;
}

/* What a motor's or friction's force (N) does to `body`. */
static void b2s3_check_drive(const b2s3_builder* b, b2s3_check* check, uint32_t body,
                             float force) {
    if (!b2s3_is_dynamic(b, body)) {
        return;
    }
    const b2MassData* mass = &b->masses[body];
    float acceleration = force / mass->mass;
    if (!(acceleration <= b2s3_range()->max_joint_acceleration)) {
        b2s3_fail(check,
                  "its motor or friction force %.9g N accelerates body %u (mass %.9g kg) by %g "
                  "m/s^2, beyond " B2S3_ENGINE "'s working range (at most %g m/s^2)",
                  (double)force, (unsigned)body, (double)mass->mass, (double)acceleration,
                  (double)b2s3_range()->max_joint_acceleration);
    }
}

/* The force a joint's motor or friction may apply, as v3 will get it. */
static float b2s3_drive_force(const b2s_joint* joint) {
    switch (joint->kind) {
    case B2S_JOINT_KIND_PRISMATIC: return joint->enable_motor ? joint->max_motor_force : 0.0f;
    case B2S_JOINT_KIND_FRICTION:
    case B2S_JOINT_KIND_MOTOR: return joint->max_force;
    default: return 0.0f;
    }
}

/* How far apart a joint's anchors start across its axis, in metres, with its bodies as
 * created. */
static float b2s3_across_axis(b2BodyId a, b2Vec2 axis_a, b2Vec2 d) {
    b2Vec2 axis = b2Normalize(b2Body_GetWorldVector(a, axis_a));
    return fabsf(b2Cross(axis, d));
}

/* How far the joint starts from satisfied, in metres, along what its kind holds rigidly,
 * with its bodies as created (what the load warning joint-starts-violated measures), and in
 * `*across` how far its anchors start apart across its axis (0 without one). */
static float b2s3_starting_violation(const b2s3_builder* b, const b2s_joint* joint,
                                     float* across) {
    b2BodyId a = b->built->bodies[joint->body_a], bb = b->built->bodies[joint->body_b];
    b2Vec2 pa = b2Body_GetWorldPoint(a, b2s3_to_b2(joint->local_anchor_a));
    b2Vec2 pb = b2Body_GetWorldPoint(bb, b2s3_to_b2(joint->local_anchor_b));
    b2Vec2 d = b2Sub(pb, pa);
    *across = 0.0f;
    switch (joint->kind) {
    case B2S_JOINT_KIND_REVOLUTE:
    case B2S_JOINT_KIND_WELD: return b2Length(d);
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_LINE:
    case B2S_JOINT_KIND_WHEEL: {
        b2Vec2 axis = b2Normalize(b2Body_GetWorldVector(a, b2s3_to_b2(joint->local_axis_a)));
        float along = b2Dot(axis, d);
        float beyond = 0.0f;
        *across = b2s3_across_axis(a, b2s3_to_b2(joint->local_axis_a), d);
        if (joint->enable_limit && joint->kind != B2S_JOINT_KIND_WHEEL) {
            beyond = b2MaxFloat(b2MaxFloat(joint->lower_limit - along, along - joint->upper_limit),
                                0.0f);
        }
        return b2MaxFloat(*across, beyond);
    }
    case B2S_JOINT_KIND_DISTANCE:
        return joint->frequency_hz > 0.0f ? 0.0f : fabsf(b2Length(d) - joint->length);
    case B2S_JOINT_KIND_ROPE: return b2MaxFloat(b2Length(d) - joint->max_length, 0.0f);
    default: return 0.0f; /* springs, motors and friction hold nothing in place */
    }
}

/* The farthest lever of one body of a joint whose other body is `other`: a line or wheel
 * joint to a body that does not turn (one that does not move, or a dynamic one without
 * rotational inertia: fixed rotation) leaves the body free to turn about an anchor that the
 * engine may not hold as far out as other joints (the range's max_lever_fixed_wheel). */
static float b2s3_lever(const b2s3_builder* b, const b2s_joint* joint, uint32_t other,
                        float lever) {
    bool wheel = joint->kind == B2S_JOINT_KIND_LINE || joint->kind == B2S_JOINT_KIND_WHEEL;
    bool turns = b2s3_is_dynamic(b, other) && b->masses[other].rotationalInertia > 0.0f;
    return wheel && !turns ? b2s3_range()->max_lever_fixed_wheel : lever;
}

static b2s3_check b2s3_joint_check(const b2s3_builder* b, const b2s_joint* joint) {
    b2s3_check check = {{0}};
    float length = b2s3_range()->max_length;
    bool anchored = joint->kind != B2S_JOINT_KIND_MOTOR;
    if (anchored) {
        b2s3_vector(&check, "LocalAnchorA", joint->local_anchor_a, length, "m");
        b2s3_vector(&check, "LocalAnchorB", joint->local_anchor_b, length, "m");
    }
    switch (joint->kind) {
    case B2S_JOINT_KIND_REVOLUTE:
        b2s3_magnitude(&check, "MotorSpeed", joint->motor_speed, b2s3_range()->max_speed, "rad/s");
        b2s3_magnitude(&check, "MaxMotorTorque", joint->max_motor_torque, b2s3_range()->max_force,
                       "N m");
        b2s3_magnitude(&check, "ReferenceAngle", joint->reference_angle, b2s3_range()->max_angle,
                       "rad");
        break;
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_LINE:
        b2s3_magnitude(&check, "LowerTranslation", joint->lower_limit, length, "m");
        b2s3_magnitude(&check, "UpperTranslation", joint->upper_limit, length, "m");
        b2s3_magnitude(&check, "MotorSpeed", joint->motor_speed, b2s3_range()->max_speed, "m/s");
        b2s3_magnitude(&check, "MaxMotorForce", joint->max_motor_force, b2s3_range()->max_force,
                       "N");
        b2s3_magnitude(&check, "ReferenceAngle", joint->reference_angle, b2s3_range()->max_angle,
                       "rad");
        break;
    case B2S_JOINT_KIND_WHEEL:
        b2s3_magnitude(&check, "MotorSpeed", joint->motor_speed, b2s3_range()->max_speed, "rad/s");
        b2s3_magnitude(&check, "MaxMotorTorque", joint->max_motor_torque, b2s3_range()->max_force,
                       "N m");
        break;
    case B2S_JOINT_KIND_DISTANCE:
        b2s3_magnitude(&check, "Length", joint->length, length, "m");
        break;
    case B2S_JOINT_KIND_ROPE:
        b2s3_magnitude(&check, "MaxLength", joint->max_length, length, "m");
        break;
    case B2S_JOINT_KIND_WELD:
        b2s3_magnitude(&check, "ReferenceAngle", joint->reference_angle, b2s3_range()->max_angle,
                       "rad");
        break;
    case B2S_JOINT_KIND_FRICTION:
    case B2S_JOINT_KIND_MOTOR:
        b2s3_magnitude(&check, "MaxForce", joint->max_force, b2s3_range()->max_force, "N");
        b2s3_magnitude(&check, "MaxTorque", joint->max_torque, b2s3_range()->max_force, "N m");
        if (joint->max_force < 0.0f || joint->max_torque < 0.0f) {
            b2s3_fail(&check, "a negative MaxForce or MaxTorque, which " B2S3_ENGINE
                              " asserts against");
        }
        if (joint->kind == B2S_JOINT_KIND_MOTOR) {
            b2s3_vector(&check, "LinearOffset", joint->linear_offset, length, "m");
            b2s3_magnitude(&check, "AngularOffset", joint->angular_offset, b2s3_range()->max_angle,
                           "rad");
            b2s3_magnitude(&check, "CorrectionFactor", joint->correction_factor,
                           b2s3_range()->max_frequency, "");
        }
        break;
    default: break;
    }
    bool axis = joint->kind == B2S_JOINT_KIND_PRISMATIC || joint->kind == B2S_JOINT_KIND_LINE ||
                joint->kind == B2S_JOINT_KIND_WHEEL;
    if (axis) {
        b2s3_vector(&check, "LocalAxisA", joint->local_axis_a, length, "m");
        if (b2s3_passed(&check) &&
            !(b2Length(b2s3_to_b2(joint->local_axis_a)) >= b2s3_range()->min_axis)) {
            b2s3_fail(&check, "LocalAxisA is shorter than %g m: " B2S3_ENGINE
                              " cannot normalise it",
                      (double)b2s3_range()->min_axis);
        }
    }
    bool spring = joint->kind == B2S_JOINT_KIND_DISTANCE || joint->kind == B2S_JOINT_KIND_WHEEL ||
                  joint->kind == B2S_JOINT_KIND_WELD;
    if (spring) {
        b2s3_magnitude(&check, "FrequencyHz", joint->frequency_hz, b2s3_range()->max_frequency, "Hz");
        b2s3_magnitude(&check, "DampingRatio", joint->damping_ratio, b2s3_range()->max_frequency,
                       "");
        if (joint->frequency_hz < 0.0f || joint->damping_ratio < 0.0f) {
            b2s3_fail(&check, "a negative FrequencyHz or DampingRatio, which " B2S3_ENGINE
                              " asserts against");
        }
    }
    bool levered =
        anchored && (b2s3_range()->friction_at_anchors || joint->kind != B2S_JOINT_KIND_FRICTION);
    if (b2s3_passed(&check) && levered) {
        float lever = joint->kind == B2S_JOINT_KIND_REVOLUTE ? b2s3_range()->max_lever_revolute
                                                             : b2s3_range()->max_lever;
        b2s3_check_anchor(b, &check, "LocalAnchorA", joint->body_a,
                          b2s3_to_b2(joint->local_anchor_a),
                          b2s3_lever(b, joint, joint->body_b, lever));
        b2s3_check_anchor(b, &check, "LocalAnchorB", joint->body_b,
                          b2s3_to_b2(joint->local_anchor_b),
                          b2s3_lever(b, joint, joint->body_a, lever));
        if (b2s3_range()->prismatic_lever_to_b && joint->kind == B2S_JOINT_KIND_PRISMATIC) {
            /* Its axis reaches body B's anchor: that is body A's lever too. */
            b2Vec2 b_anchor = b2Body_GetWorldPoint(b->built->bodies[joint->body_b],
                                                   b2s3_to_b2(joint->local_anchor_b));
            b2s3_check_anchor(b, &check, "LocalAnchorB, as body A's lever", joint->body_a,
                              b2Body_GetLocalPoint(b->built->bodies[joint->body_a], b_anchor),
                              lever);
        }
    }
    if (b2s3_passed(&check)) {
        b2s3_check_drive(b, &check, joint->body_a, b2s3_drive_force(joint));
        b2s3_check_drive(b, &check, joint->body_b, b2s3_drive_force(joint));
    }
    return check;
}

/* What the working-range sweeps of docs/working-range.md measured of joints that start
 * violated: a line or wheel joint further than the range's max_wheel_violation from
 * satisfied, or whose anchors start more than its max_wheel_violation_gyrations radii of
 * gyration apart across its axis between two dynamic bodies, flings its bodies off; a body
 * pulled by two joints that start more than its max_pulled_violation from satisfied makes
 * the solver assert. The first such joint of any other kind on a body is built, the later ones are
 * not. */
static void b2s3_check_violation(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                 b2s3_check* check) {
    float across = 0.0f;
    float violation = b2s3_starting_violation(b, joint, &across);
    bool wheel = joint->kind == B2S_JOINT_KIND_LINE || joint->kind == B2S_JOINT_KIND_WHEEL;
    if (wheel && violation > b2s3_range()->max_wheel_violation) {
        b2s3_fail(check,
                  "it starts %.9g m from satisfied: a line or wheel joint further than %g m from "
                  "satisfied lies beyond " B2S3_ENGINE "'s working range (its solver flings the "
                  "bodies apart)",
                  (double)violation, (double)b2s3_range()->max_wheel_violation);
        return;
    }
    if (wheel && b2s3_is_dynamic(b, joint->body_a) && b2s3_is_dynamic(b, joint->body_b)) {
        float gyration = fminf(b2s3_gyration(&b->masses[joint->body_a]),
                               b2s3_gyration(&b->masses[joint->body_b]));
        float bound = b2s3_range()->max_wheel_violation_gyrations * gyration;
        if (across > b2s3_range()->linear_slop && !(across <= bound)) {
            b2s3_fail(check,
                      "it starts violated by %.9g m across its axis between two dynamic "
                      "bodies, beyond " B2S3_ENGINE "'s working range (at most %g radii of "
                      "gyration, %.9g m), where its solver throws them off",
                      (double)across, (double)b2s3_range()->max_wheel_violation_gyrations, (double)bound);
            return;
        }
    }
    if (wheel || !(violation > b2s3_range()->max_pulled_violation)) {
        return;
    }
    uint32_t bodies[2] = {joint->body_a, joint->body_b};
    for (int i = 0; i < 2; ++i) {
        if (b->pulled[bodies[i]] != 0) {
            b2s3_fail(check,
                      "it starts %.9g m from satisfied, and joint %u already pulls body %u from "
                      "further than %g m: two such joints on one body lie beyond " B2S3_ENGINE
                      "'s working range (its solver asserts)",
                      (double)violation, (unsigned)(b->pulled[bodies[i]] - 1),
                      (unsigned)bodies[i], (double)b2s3_range()->max_pulled_violation);
            return;
        }
    }
    for (int i = 0; i < 2; ++i) {
        if (b2s3_is_dynamic(b, bodies[i])) {
            b->pulled[bodies[i]] = index + 1;
        }
    }
}

/* The bodies every joint def has; false (and a report) when one is missing. */
static bool b2s3_connect(b2s3_builder* b, uint32_t index, const b2s_joint* joint, b2BodyId* a,
                         b2BodyId* bb) {
    *a = b2s3_created_body(b, joint->body_a);
    *bb = b2s3_created_body(b, joint->body_b);
    if (B2_IS_NULL((*a)) || B2_IS_NULL((*bb))) {
        B2S3_REPORT(b, B2S_CODE_SKIPPED_DEPENDENT, "joint", index, joint->name,
                    "it names body %u, which was not created; joint skipped",
                    (unsigned)(B2_IS_NULL((*a)) ? joint->body_a : joint->body_b));
        return false;
    }
    if (joint->body_a == joint->body_b) {
        B2S3_REPORT(b, B2S_CODE_JOINT_SELF_REFERENCE, "joint", index, joint->name,
                    "it connects a body to itself; joint skipped");
        return false;
    }
    return true;
}

/* Limits in the order v3 asserts; a disabled pair in the wrong order has no effect, so it
 * is passed swapped (an enabled one the loader refuses). */
static void b2s3_ordered_limits(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                const char* lower_name, const char* upper_name, float* lower,
                                float* upper) {
    if (*lower > *upper) {
        float swap = *lower;
        *lower = *upper;
        *upper = swap;
        B2S3_REPORT(b, B2S_CODE_BAD_LIMIT, "joint", index, joint->name,
                    "%s %.9g lies above %s %.9g, which " B2S3_ENGINE " asserts against; they "
                    "were passed swapped",
                    lower_name, (double)joint->lower_limit, upper_name,
                    (double)joint->upper_limit);
    }
}

static float b2s3_clamped(float value, float low, float high) {
    return value < low ? low : value > high ? high : value;
}

/* The scene joint's anchors, unit axis and reference angle, for the version's frames. */
static b2s3_frames b2s3_frames_from(const b2s_joint* joint) {
    b2s3_frames f;
    f.anchor_a = b2s3_to_b2(joint->local_anchor_a);
    f.anchor_b = b2s3_to_b2(joint->local_anchor_b);
    f.axis = b2Normalize(b2s3_to_b2(joint->local_axis_a));
    f.reference_angle = joint->reference_angle;
    return f;
}

#define B2S3_CONNECT(def, joint, a, bb)                                                        \
    do {                                                                                       \
        B2S3_JOINT_BASE(def).bodyIdA = (a);                                                    \
        B2S3_JOINT_BASE(def).bodyIdB = (bb);                                                   \
        B2S3_JOINT_BASE(def).collideConnected = (joint)->collide_connected;                    \
    } while (0)

static b2JointId b2s3_make_revolute(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                    b2BodyId a, b2BodyId bb) {
    b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_REVOLUTE_FRAMES(def, f);
    float lower = joint->lower_limit, upper = joint->upper_limit;
    b2s3_ordered_limits(b, index, joint, "LowerAngle", "UpperAngle", &lower, &upper);
    /* v3 asserts that a limit lies within +-0.99 pi (v3.2's snapshot even when it is off). */
    float bound = b2s3_range()->max_revolute_limit;
    def.lowerAngle = b2s3_clamped(lower, -bound, bound);
    def.upperAngle = b2s3_clamped(upper, -bound, bound);
    if (joint->enable_limit && (def.lowerAngle != lower || def.upperAngle != upper)) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_JOINT, "joint", index, joint->name,
                    "its limit [%.9g, %.9g] reaches beyond " B2S3_ENGINE "'s +-0.99 pi; it was "
                    "clamped to [%.9g, %.9g]",
                    (double)lower, (double)upper, (double)def.lowerAngle,
                    (double)def.upperAngle);
    }
    def.enableLimit = joint->enable_limit;
    def.enableMotor = joint->enable_motor;
    def.motorSpeed = joint->motor_speed;
    def.maxMotorTorque = joint->max_motor_torque;
    return b2CreateRevoluteJoint(b->world, &def);
}

static b2JointId b2s3_make_prismatic(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                     b2BodyId a, b2BodyId bb) {
    b2PrismaticJointDef def = b2DefaultPrismaticJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_PRISMATIC_FRAMES(def, f);
    def.lowerTranslation = joint->lower_limit;
    def.upperTranslation = joint->upper_limit;
    b2s3_ordered_limits(b, index, joint, "LowerTranslation", "UpperTranslation",
                        &def.lowerTranslation, &def.upperTranslation);
    def.enableLimit = joint->enable_limit;
    def.enableMotor = joint->enable_motor;
    def.maxMotorForce = joint->max_motor_force;
    def.motorSpeed = joint->motor_speed;
    return b2CreatePrismaticJoint(b->world, &def);
}

/* v3 asserts a length above 0 and raises it to its linear slop. */
static float b2s3_joint_length(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                               const char* field, float length) {
    float slop = b2s3_range()->linear_slop;
    if (length >= slop) {
        return length;
    }
    B2S3_REPORT(b, B2S_CODE_LOSSY_JOINT, "joint", index, joint->name,
                "%s %.9g lies under " B2S3_ENGINE "'s shortest joint length, %g m, which was "
                "used",
                field, (double)length, (double)slop);
    return slop;
}

static b2DistanceJointDef b2s3_distance_def(const b2s_joint* joint, b2BodyId a, b2BodyId bb) {
    b2DistanceJointDef def = b2DefaultDistanceJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_ANCHOR_FRAMES(def, f);
    return def;
}

/* FrequencyHz 0 is a rigid rod; above it, a spring around Length. */
static b2JointId b2s3_make_distance(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                    b2BodyId a, b2BodyId bb) {
    b2DistanceJointDef def = b2s3_distance_def(joint, a, bb);
    def.length = b2s3_joint_length(b, index, joint, "Length", joint->length);
    if (joint->frequency_hz > 0.0f) {
        def.enableSpring = true;
        def.hertz = joint->frequency_hz;
        def.dampingRatio = joint->damping_ratio;
    }
    return b2CreateDistanceJoint(b->world, &def);
}

/* A rope is slack up to MaxLength: a spring of 0 Hz with the upper limit on. */
static b2JointId b2s3_make_rope(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                b2BodyId a, b2BodyId bb) {
    b2DistanceJointDef def = b2s3_distance_def(joint, a, bb);
    def.length = b2s3_joint_length(b, index, joint, "MaxLength", joint->max_length);
    def.enableSpring = true;
    def.hertz = 0.0f;
    def.enableLimit = true;
    def.minLength = 0.0f;
    def.maxLength = def.length;
    return b2CreateDistanceJoint(b->world, &def);
}

static b2WheelJointDef b2s3_wheel_def(const b2s_joint* joint, b2BodyId a, b2BodyId bb) {
    b2WheelJointDef def = b2DefaultWheelJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_AXIS_FRAMES(def, f);
    return def;
}

/* Box2D 2.1's line joint: a wheel joint without a spring (v3.2's default has one). Its
 * motor drove the translation; v3's wheel motor drives the rotation, so it stays off. */
static b2JointId b2s3_make_line(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                b2BodyId a, b2BodyId bb) {
    b2WheelJointDef def = b2s3_wheel_def(joint, a, bb);
    def.enableSpring = false;
    def.lowerTranslation = joint->lower_limit;
    def.upperTranslation = joint->upper_limit;
    b2s3_ordered_limits(b, index, joint, "LowerTranslation", "UpperTranslation",
                        &def.lowerTranslation, &def.upperTranslation);
    def.enableLimit = joint->enable_limit;
    if (joint->enable_motor) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_LINE_MOTOR, "joint", index, joint->name,
                    B2S3_ENGINE " has no linear motor on a line (wheel) joint; the motor is off");
    }
    return b2CreateWheelJoint(b->world, &def);
}

static b2JointId b2s3_make_wheel(b2s3_builder* b, const b2s_joint* joint, b2BodyId a,
                                 b2BodyId bb) {
    b2WheelJointDef def = b2s3_wheel_def(joint, a, bb);
    def.enableSpring = true;
    def.hertz = joint->frequency_hz;
    def.dampingRatio = joint->damping_ratio;
    def.enableMotor = joint->enable_motor;
    def.maxMotorTorque = joint->max_motor_torque;
    def.motorSpeed = joint->motor_speed;
    return b2CreateWheelJoint(b->world, &def);
}

static b2JointId b2s3_make_weld(b2s3_builder* b, const b2s_joint* joint, b2BodyId a,
                                b2BodyId bb) {
    b2WeldJointDef def = b2DefaultWeldJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_WELD_FRAMES(def, f);
    def.linearHertz = 0.0f;
    def.angularHertz = joint->frequency_hz;
    def.angularDampingRatio = joint->damping_ratio;
    return b2CreateWeldJoint(b->world, &def);
}

/* v3 has no friction joint: a motor joint that drives no velocity does its work, the
 * version's way (v31.h, v32.h). */
static b2JointId b2s3_make_friction(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                    b2BodyId a, b2BodyId bb) {
    b2MotorJointDef def = b2DefaultMotorJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    char loss[B2S3_LOSS_SIZE];
    if (b2s3_friction_def(&def, joint, b2s3_frames_from(joint), loss)) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_JOINT, "joint", index, joint->name, "%s", loss);
    }
    return b2CreateMotorJoint(b->world, &def);
}

static b2JointId b2s3_make_motor(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                 b2BodyId a, b2BodyId bb) {
    b2MotorJointDef def = b2DefaultMotorJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    char losses[2][B2S3_LOSS_SIZE];
    int count = b2s3_motor_def(&def, joint, losses);
    for (int i = 0; i < count; ++i) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_JOINT, "joint", index, joint->name, "%s", losses[i]);
    }
    return b2CreateMotorJoint(b->world, &def);
}

static void b2s3_make_joint(b2s3_builder* b, uint32_t index) {
    const b2s_joint* joint = &b->view->joints[index];
    const char* missing = NULL;
    switch (joint->kind) {
    case B2S_JOINT_KIND_PULLEY: missing = "a pulley joint"; break;
    case B2S_JOINT_KIND_GEAR: missing = "a gear joint"; break;
    case B2S_JOINT_KIND_UNSUPPORTED: missing = "a Farseer-only joint"; break;
    default:
        if (joint->kind > B2S_JOINT_KIND_UNSUPPORTED) {
            B2S3_REPORT(b, B2S_CODE_UNKNOWN_TYPE, "joint", index, joint->name,
                        "unknown joint kind %u; joint skipped", (unsigned)joint->kind);
            return;
        }
    }
    if (missing != NULL) {
        B2S3_REPORT(b, B2S_CODE_SKIPPED_JOINT, "joint", index, joint->name,
                    B2S3_ENGINE " has no form for %s; joint skipped", missing);
        return;
    }
    b2BodyId a, bb;
    if (!b2s3_connect(b, index, joint, &a, &bb)) {
        return;
    }
    b2s3_check check = b2s3_joint_check(b, joint);
    if (b2s3_passed(&check)) {
        b2s3_check_violation(b, index, joint, &check);
    }
    if (!b2s3_passed(&check)) {
        b2s3_beyond(b, &check, "joint", index, joint->name, "");
        return;
    }
    b2JointId* out = &b->built->joints[index];
    switch (joint->kind) {
    case B2S_JOINT_KIND_REVOLUTE: *out = b2s3_make_revolute(b, index, joint, a, bb); break;
    case B2S_JOINT_KIND_PRISMATIC: *out = b2s3_make_prismatic(b, index, joint, a, bb); break;
    case B2S_JOINT_KIND_DISTANCE: *out = b2s3_make_distance(b, index, joint, a, bb); break;
    case B2S_JOINT_KIND_ROPE: *out = b2s3_make_rope(b, index, joint, a, bb); break;
    case B2S_JOINT_KIND_LINE: *out = b2s3_make_line(b, index, joint, a, bb); break;
    case B2S_JOINT_KIND_WHEEL: *out = b2s3_make_wheel(b, joint, a, bb); break;
    case B2S_JOINT_KIND_WELD: *out = b2s3_make_weld(b, joint, a, bb); break;
    case B2S_JOINT_KIND_FRICTION: *out = b2s3_make_friction(b, index, joint, a, bb); break;
    case B2S_JOINT_KIND_MOTOR: *out = b2s3_make_motor(b, index, joint, a, bb); break;
    default: break;
    }
}
