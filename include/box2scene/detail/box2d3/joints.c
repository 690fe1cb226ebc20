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
    if (!(compliance <= B2S3_LIMIT(MAX_COMPLIANCE))) {
        b2s3_fail(check,
                  "%s: the joint acts %.9g m from the centre of mass of body %u (mass %.9g kg, "
                  "inertia %.9g kg m^2), where 1/m + r^2/I = %g 1/kg lies beyond " B2S3_ENGINE
                  "'s working range (at most %g 1/kg)",
                  field, (double)r, (unsigned)body, (double)mass->mass, (double)inertia,
                  (double)compliance, (double)B2S3_LIMIT(MAX_COMPLIANCE));
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
    if (!(acceleration <= B2S3_LIMIT(MAX_JOINT_ACCELERATION))) {
        b2s3_fail(check,
                  "its motor or friction force %.9g N accelerates body %u (mass %.9g kg) by %g "
                  "m/s^2, beyond " B2S3_ENGINE "'s working range (at most %g m/s^2)",
                  (double)force, (unsigned)body, (double)mass->mass, (double)acceleration,
                  (double)B2S3_LIMIT(MAX_JOINT_ACCELERATION));
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

/* How far a line or wheel joint starts from what it holds, in metres: its anchors' distance
 * across the axis (0 for the other kinds, which v3 pulls together however far apart they
 * start). */
static float b2s3_initial_violation(const b2s3_builder* b, const b2s_joint* joint) {
    b2BodyId a = b->built->bodies[joint->body_a], bb = b->built->bodies[joint->body_b];
    b2Transform ta = b2Body_GetTransform(a), tb = b2Body_GetTransform(bb);
    b2Vec2 pa = b2TransformPoint(ta, b2s3_to_b2(joint->local_anchor_a));
    b2Vec2 pb = b2TransformPoint(tb, b2s3_to_b2(joint->local_anchor_b));
    b2Vec2 d = b2Sub(pb, pa);
    switch (joint->kind) {
    case B2S_JOINT_KIND_LINE:
    case B2S_JOINT_KIND_WHEEL: {
        b2Vec2 axis = b2RotateVector(ta.q, b2Normalize(b2s3_to_b2(joint->local_axis_a)));
        return fabsf(b2Cross(axis, d));
    }
    default: return 0.0f;
    }
}

static b2s3_check b2s3_joint_check(const b2s3_builder* b, const b2s_joint* joint) {
    b2s3_check check = {{0}};
    float length = B2S3_LIMIT(MAX_LENGTH);
    bool anchored = joint->kind != B2S_JOINT_KIND_MOTOR;
    if (anchored) {
        b2s3_vector(&check, "LocalAnchorA", joint->local_anchor_a, length, "m");
        b2s3_vector(&check, "LocalAnchorB", joint->local_anchor_b, length, "m");
    }
    switch (joint->kind) {
    case B2S_JOINT_KIND_REVOLUTE:
        b2s3_magnitude(&check, "MotorSpeed", joint->motor_speed, B2S3_LIMIT(MAX_SPEED), "rad/s");
        b2s3_magnitude(&check, "MaxMotorTorque", joint->max_motor_torque, B2S3_LIMIT(MAX_FORCE),
                       "N m");
        b2s3_magnitude(&check, "ReferenceAngle", joint->reference_angle, B2S3_LIMIT(MAX_ANGLE),
                       "rad");
        break;
    case B2S_JOINT_KIND_PRISMATIC:
    case B2S_JOINT_KIND_LINE:
        b2s3_magnitude(&check, "LowerTranslation", joint->lower_limit, length, "m");
        b2s3_magnitude(&check, "UpperTranslation", joint->upper_limit, length, "m");
        b2s3_magnitude(&check, "MotorSpeed", joint->motor_speed, B2S3_LIMIT(MAX_SPEED), "m/s");
        b2s3_magnitude(&check, "MaxMotorForce", joint->max_motor_force, B2S3_LIMIT(MAX_FORCE),
                       "N");
        b2s3_magnitude(&check, "ReferenceAngle", joint->reference_angle, B2S3_LIMIT(MAX_ANGLE),
                       "rad");
        break;
    case B2S_JOINT_KIND_WHEEL:
        b2s3_magnitude(&check, "MotorSpeed", joint->motor_speed, B2S3_LIMIT(MAX_SPEED), "rad/s");
        b2s3_magnitude(&check, "MaxMotorTorque", joint->max_motor_torque, B2S3_LIMIT(MAX_FORCE),
                       "N m");
        break;
    case B2S_JOINT_KIND_DISTANCE:
        b2s3_magnitude(&check, "Length", joint->length, length, "m");
        break;
    case B2S_JOINT_KIND_ROPE:
        b2s3_magnitude(&check, "MaxLength", joint->max_length, length, "m");
        break;
    case B2S_JOINT_KIND_WELD:
        b2s3_magnitude(&check, "ReferenceAngle", joint->reference_angle, B2S3_LIMIT(MAX_ANGLE),
                       "rad");
        break;
    case B2S_JOINT_KIND_FRICTION:
    case B2S_JOINT_KIND_MOTOR:
        b2s3_magnitude(&check, "MaxForce", joint->max_force, B2S3_LIMIT(MAX_FORCE), "N");
        b2s3_magnitude(&check, "MaxTorque", joint->max_torque, B2S3_LIMIT(MAX_FORCE), "N m");
        if (joint->max_force < 0.0f || joint->max_torque < 0.0f) {
            b2s3_fail(&check, "a negative MaxForce or MaxTorque, which " B2S3_ENGINE
                              " asserts against");
        }
        if (joint->kind == B2S_JOINT_KIND_MOTOR) {
            b2s3_vector(&check, "LinearOffset", joint->linear_offset, length, "m");
            b2s3_magnitude(&check, "AngularOffset", joint->angular_offset, B2S3_LIMIT(MAX_ANGLE),
                           "rad");
            b2s3_magnitude(&check, "CorrectionFactor", joint->correction_factor,
                           B2S3_LIMIT(MAX_FREQUENCY), "");
        }
        break;
    default: break;
    }
    bool axis = joint->kind == B2S_JOINT_KIND_PRISMATIC || joint->kind == B2S_JOINT_KIND_LINE ||
                joint->kind == B2S_JOINT_KIND_WHEEL;
    if (axis) {
        b2s3_vector(&check, "LocalAxisA", joint->local_axis_a, length, "m");
        if (b2s3_passed(&check) &&
            !(b2Length(b2s3_to_b2(joint->local_axis_a)) >= B2S3_LIMIT(MIN_AXIS))) {
            b2s3_fail(&check, "LocalAxisA is shorter than %g m: " B2S3_ENGINE
                              " cannot normalise it",
                      (double)B2S3_LIMIT(MIN_AXIS));
        }
    }
    bool spring = joint->kind == B2S_JOINT_KIND_DISTANCE || joint->kind == B2S_JOINT_KIND_WHEEL ||
                  joint->kind == B2S_JOINT_KIND_WELD;
    if (spring) {
        b2s3_magnitude(&check, "FrequencyHz", joint->frequency_hz, B2S3_LIMIT(MAX_FREQUENCY), "Hz");
        b2s3_magnitude(&check, "DampingRatio", joint->damping_ratio, B2S3_LIMIT(MAX_FREQUENCY),
                       "");
        if (joint->frequency_hz < 0.0f || joint->damping_ratio < 0.0f) {
            b2s3_fail(&check, "a negative FrequencyHz or DampingRatio, which " B2S3_ENGINE
                              " asserts against");
        }
    }
    if (b2s3_passed(&check) && anchored) {
        float lever = joint->kind == B2S_JOINT_KIND_REVOLUTE ? B2S3_LIMIT(MAX_LEVER_REVOLUTE)
                                                             : B2S3_LIMIT(MAX_LEVER);
        b2s3_check_anchor(b, &check, "LocalAnchorA", joint->body_a,
                          b2s3_to_b2(joint->local_anchor_a), lever);
        b2s3_check_anchor(b, &check, "LocalAnchorB", joint->body_b,
                          b2s3_to_b2(joint->local_anchor_b), lever);
    }
    if (b2s3_passed(&check)) {
        b2s3_check_drive(b, &check, joint->body_a, b2s3_drive_force(joint));
        b2s3_check_drive(b, &check, joint->body_b, b2s3_drive_force(joint));
    }
    if (b2s3_passed(&check) && b2s3_is_dynamic(b, joint->body_a) &&
        b2s3_is_dynamic(b, joint->body_b)) {
        float violation = b2s3_initial_violation(b, joint);
        float gyration = fminf(b2s3_gyration(&b->masses[joint->body_a]),
                               b2s3_gyration(&b->masses[joint->body_b]));
        float bound = B2S3_LIMIT(MAX_INITIAL_VIOLATION) * gyration;
        if (violation > B2S3_LINEAR_SLOP && !(violation <= bound)) {
            b2s3_fail(&check,
                      "it starts violated by %.9g m across its axis between two dynamic "
                      "bodies, beyond " B2S3_ENGINE "'s working range (at most %g radii of "
                      "gyration, %.9g m), where its solver throws them off",
                      (double)violation, (double)B2S3_LIMIT(MAX_INITIAL_VIOLATION),
                      (double)bound);
        }
    }
    return check;
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

/* v3 asserts that a revolute limit lies within +-0.99 pi (v3.2's snapshot even when the
 * limit is off). */
#define B2S3_REVOLUTE_LIMIT (0.99f * 3.14159265359f)

static b2JointId b2s3_make_revolute(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                    b2BodyId a, b2BodyId bb) {
    b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_ANGLE_FRAMES(def, f);
    float lower = joint->lower_limit, upper = joint->upper_limit;
    b2s3_ordered_limits(b, index, joint, "LowerAngle", "UpperAngle", &lower, &upper);
    def.lowerAngle = b2s3_clamped(lower, -B2S3_REVOLUTE_LIMIT, B2S3_REVOLUTE_LIMIT);
    def.upperAngle = b2s3_clamped(upper, -B2S3_REVOLUTE_LIMIT, B2S3_REVOLUTE_LIMIT);
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
    if (length >= B2S3_LINEAR_SLOP) {
        return length;
    }
    B2S3_REPORT(b, B2S_CODE_LOSSY_JOINT, "joint", index, joint->name,
                "%s %.9g lies under " B2S3_ENGINE "'s shortest joint length, %g m, which was "
                "used",
                field, (double)length, (double)B2S3_LINEAR_SLOP);
    return B2S3_LINEAR_SLOP;
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
    B2S3_ANGLE_FRAMES(def, f);
    def.linearHertz = 0.0f;
    def.angularHertz = joint->frequency_hz;
    def.angularDampingRatio = joint->damping_ratio;
    return b2CreateWeldJoint(b->world, &def);
}

/* v3 has no friction joint: a motor joint that drives no velocity does its work (v32.h). */
static b2JointId b2s3_make_friction(b2s3_builder* b, const b2s_joint* joint, b2BodyId a,
                                    b2BodyId bb) {
    b2MotorJointDef def = b2DefaultMotorJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    b2s3_frames f = b2s3_frames_from(joint);
    B2S3_ANCHOR_FRAMES(def, f);
    b2s3_friction_def(&def, joint);
    return b2CreateMotorJoint(b->world, &def);
}

static b2JointId b2s3_make_motor(b2s3_builder* b, uint32_t index, const b2s_joint* joint,
                                 b2BodyId a, b2BodyId bb) {
    b2MotorJointDef def = b2DefaultMotorJointDef();
    B2S3_CONNECT(def, joint, a, bb);
    const char* loss = b2s3_motor_def(&def, joint);
    if (loss != NULL) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_JOINT, "joint", index, joint->name, "%s", loss);
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
    case B2S_JOINT_KIND_FRICTION: *out = b2s3_make_friction(b, joint, a, bb); break;
    case B2S_JOINT_KIND_MOTOR: *out = b2s3_make_motor(b, index, joint, a, bb); break;
    default: break;
    }
}
