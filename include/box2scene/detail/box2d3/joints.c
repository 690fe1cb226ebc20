/*
 * Joints: each plan joint through its kind's def, the version's way of taking anchors, axes
 * and reference angles (v31.h: fields of each def; v32.h: the bodies' local frames).
 */

#define B2S3_CONNECT(def, b, joint)                                                            \
    do {                                                                                       \
        B2S3_JOINT_BASE(def).bodyIdA = (b)->built->bodies[(joint)->body_a];                    \
        B2S3_JOINT_BASE(def).bodyIdB = (b)->built->bodies[(joint)->body_b];                    \
        B2S3_JOINT_BASE(def).collideConnected = (joint)->collide_connected;                    \
    } while (0)

static b2JointId b2s3_make_revolute(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
    B2S3_CONNECT(def, b, joint);
    B2S3_REVOLUTE_FRAMES(def, joint);
    def.lowerAngle = joint->lower;
    def.upperAngle = joint->upper;
    def.enableLimit = joint->enable_limit;
    def.enableMotor = joint->enable_motor;
    def.motorSpeed = joint->motor_speed;
    def.maxMotorTorque = joint->max_motor;
    return b2CreateRevoluteJoint(b->world, &def);
}

static b2JointId b2s3_make_prismatic(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2PrismaticJointDef def = b2DefaultPrismaticJointDef();
    B2S3_CONNECT(def, b, joint);
    B2S3_PRISMATIC_FRAMES(def, joint);
    def.lowerTranslation = joint->lower;
    def.upperTranslation = joint->upper;
    def.enableLimit = joint->enable_limit;
    def.enableMotor = joint->enable_motor;
    def.maxMotorForce = joint->max_motor;
    def.motorSpeed = joint->motor_speed;
    return b2CreatePrismaticJoint(b->world, &def);
}

/* A rod, a spring around its length, or (its limit on) a rope. */
static b2JointId b2s3_make_distance(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2DistanceJointDef def = b2DefaultDistanceJointDef();
    B2S3_CONNECT(def, b, joint);
    B2S3_ANCHOR_FRAMES(def, joint);
    def.length = joint->length;
    def.enableSpring = joint->enable_spring;
    def.hertz = joint->hertz;
    def.dampingRatio = joint->damping_ratio;
    if (joint->enable_limit) {
        def.enableLimit = true;
        def.minLength = joint->min_length;
        def.maxLength = joint->max_length;
    }
    return b2CreateDistanceJoint(b->world, &def);
}

/* A wheel, or a line joint: a wheel without a spring, whose limits may be on. */
static b2JointId b2s3_make_wheel(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2WheelJointDef def = b2DefaultWheelJointDef();
    B2S3_CONNECT(def, b, joint);
    B2S3_AXIS_FRAMES(def, joint);
    def.enableSpring = joint->enable_spring;
    if (joint->enable_spring) {
        def.hertz = joint->hertz;
        def.dampingRatio = joint->damping_ratio;
    }
    def.lowerTranslation = joint->lower;
    def.upperTranslation = joint->upper;
    def.enableLimit = joint->enable_limit;
    def.enableMotor = joint->enable_motor;
    def.maxMotorTorque = joint->max_motor;
    def.motorSpeed = joint->motor_speed;
    return b2CreateWheelJoint(b->world, &def);
}

static b2JointId b2s3_make_weld(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2WeldJointDef def = b2DefaultWeldJointDef();
    B2S3_CONNECT(def, b, joint);
    B2S3_WELD_FRAMES(def, joint);
    def.linearHertz = 0.0f;
    def.angularHertz = joint->hertz;
    def.angularDampingRatio = joint->damping_ratio;
    return b2CreateWeldJoint(b->world, &def);
}

/* v3 has no friction joint: a motor joint that drives no velocity does its work, the
 * version's way (v31.h, v32.h); so does its motor joint. */
static b2JointId b2s3_make_motor(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2MotorJointDef def = b2DefaultMotorJointDef();
    B2S3_CONNECT(def, b, joint);
    if (joint->kind == B2S_PLAN_JOINT_KIND_FRICTION) {
        b2s3_friction_def(&def, joint);
    } else {
        b2s3_motor_def(&def, joint);
    }
    return b2CreateMotorJoint(b->world, &def);
}

static void b2s3_make_joint(b2s3_builder* b, const b2s_plan_joint* joint) {
    b2JointId* out = &b->built->joints[joint->joint];
    switch (joint->kind) {
    case B2S_PLAN_JOINT_KIND_REVOLUTE: *out = b2s3_make_revolute(b, joint); break;
    case B2S_PLAN_JOINT_KIND_PRISMATIC: *out = b2s3_make_prismatic(b, joint); break;
    case B2S_PLAN_JOINT_KIND_DISTANCE: *out = b2s3_make_distance(b, joint); break;
    case B2S_PLAN_JOINT_KIND_WHEEL: *out = b2s3_make_wheel(b, joint); break;
    case B2S_PLAN_JOINT_KIND_WELD: *out = b2s3_make_weld(b, joint); break;
    case B2S_PLAN_JOINT_KIND_FRICTION:
    case B2S_PLAN_JOINT_KIND_MOTOR: *out = b2s3_make_motor(b, joint); break;
    default: break;
    }
}
