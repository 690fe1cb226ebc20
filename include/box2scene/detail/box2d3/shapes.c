/*
 * Shapes: the v3 shapes a plan body's fixtures make, from the plan's geometry (a circle, a
 * polygon's hull, a segment, or a chain's points).
 */

/* The filter whole: v3's bits are 64, the scene's fewer. */
static b2Filter b2s3_filter(const b2s_filter* filter) {
    b2Filter out = b2DefaultFilter();
    out.categoryBits = filter->category_bits;
    out.maskBits = filter->mask_bits;
    out.groupIndex = filter->group_index;
    return out;
}

/* The plan shape's points as v3 vectors, in the builder's room (false when memory runs
 * out). */
static bool b2s3_points(b2s3_builder* b, const b2s_plan_shape* shape) {
    uint32_t count = shape->points.count;
    if (count > b->point_capacity) {
        b2Vec2* points = (b2Vec2*)realloc(b->points, count * sizeof(b2Vec2));
        if (points == NULL) {
            b->list.out_of_memory = true;
            return false;
        }
        b->points = points;
        b->point_capacity = count;
    }
    for (uint32_t i = 0; i < count; ++i) {
        b->points[i] = b2s3_to_b2(b->plan->points[shape->points.first + i]);
    }
    return true;
}

/* A polygon of radius 0 from the plan's hull, which is b2ComputeHull's own. */
static b2Polygon b2s3_polygon(const b2s3_builder* b, const b2s_plan_shape* shape) {
    b2Hull hull;
    memset(&hull, 0, sizeof hull);
    hull.count = (int)shape->points.count;
    for (int i = 0; i < hull.count; ++i) {
        hull.points[i] = b->points[i];
    }
    return b2MakePolygon(&hull, 0.0f);
}

static void b2s3_make_shape(b2s3_builder* b, const b2s_plan_shape* shape, b2BodyId body) {
    b2ShapeDef def = b2DefaultShapeDef();
    def.density = shape->density;
    def.material.friction = shape->friction;
    def.material.restitution = shape->restitution;
    def.filter = b2s3_filter(&shape->filter);
    def.isSensor = shape->is_sensor;
    /* Box2D 2.x's sensors saw every shape; v3's see those with sensor events on. */
    def.enableSensorEvents = true;
    /* One mass update per body, after all its shapes: linear in the shapes, not quadratic. */
    def.updateBodyMass = false;
    if (!b2s3_points(b, shape)) {
        return;
    }
    b2ShapeId* out = &b->built->shapes[shape->slot];
    switch (shape->kind) {
    case B2S_PLAN_SHAPE_KIND_CIRCLE: {
        b2Circle circle = {b2s3_to_b2(shape->center), shape->radius};
        *out = b2CreateCircleShape(body, &def, &circle);
        break;
    }
    case B2S_PLAN_SHAPE_KIND_POLYGON: {
        b2Polygon polygon = b2s3_polygon(b, shape);
        *out = b2CreatePolygonShape(body, &def, &polygon);
        break;
    }
    case B2S_PLAN_SHAPE_KIND_SEGMENT: {
        b2Segment segment = {b->points[0], b->points[1]};
        *out = b2CreateSegmentShape(body, &def, &segment);
        break;
    }
    case B2S_PLAN_SHAPE_KIND_CHAIN:
    case B2S_PLAN_SHAPE_KIND_LOOP:
        if (!b2s3_create_chain(b->built, &b->chain_capacity, shape->slot, body, &def, b->points,
                               (int)shape->points.count,
                               shape->kind == B2S_PLAN_SHAPE_KIND_LOOP)) {
            b->list.out_of_memory = true;
        }
        break;
    default: break;
    }
}
