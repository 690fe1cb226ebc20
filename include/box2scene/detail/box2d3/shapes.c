/*
 * Shapes: a scene shape as v3 geometry (made once, whatever the fixtures naming it), and
 * the v3 shapes a fixture makes of it on one body.
 */

static b2s3_check b2s3_shape_check(const b2s_shape* shape, const b2s_vec2* points,
                                   uint32_t count) {
    b2s3_check check = {{0}};
    bool edge = shape->kind == B2S_SHAPE_KIND_EDGE;
    char field[32];
    if (shape->kind == B2S_SHAPE_KIND_CIRCLE) {
        b2s3_magnitude(&check, "Radius", shape->radius, b2s3_range()->max_length, "m");
        b2s3_vector(&check, "Position", shape->position, b2s3_range()->max_length, "m");
    }
    for (uint32_t i = 0; i < count && b2s3_passed(&check); ++i) {
        snprintf(field, sizeof field, edge ? "Vertex%u" : "Vertex %u", edge ? i + 1 : i);
        b2s3_vector(&check, field, points[i], b2s3_range()->max_length, "m");
    }
    if (shape->kind == B2S_SHAPE_KIND_POLYGON && shape->centroid_given) {
        b2s3_vector(&check, "Centroid", shape->centroid, b2s3_range()->max_length, "m");
    }
    bool ghosts = edge || (shape->kind == B2S_SHAPE_KIND_CHAIN && !shape->is_loop);
    if (ghosts && shape->has_prev_vertex) {
        b2s3_vector(&check, edge ? "Vertex0" : "PrevVertex", shape->prev_vertex,
                    b2s3_range()->max_length, "m");
    }
    if (ghosts && shape->has_next_vertex) {
        b2s3_vector(&check, edge ? "Vertex3" : "NextVertex", shape->next_vertex,
                    b2s3_range()->max_length, "m");
    }
    return check;
}

static bool b2s3_vertex_count_fits(const b2s_shape* shape, uint32_t count) {
    switch (shape->kind) {
    case B2S_SHAPE_KIND_POLYGON: return count >= 2 && count <= B2_MAX_POLYGON_VERTICES;
    case B2S_SHAPE_KIND_EDGE: return count == 2;
    case B2S_SHAPE_KIND_CHAIN: return count >= (shape->is_loop ? 3u : 2u);
    default: return true;
    }
}

/* v3 refuses (asserts against) a segment no longer than its linear slop. */
static bool b2s3_segment_long_enough(b2Vec2 a, b2Vec2 b) {
    return b2DistanceSquared(a, b) > b2s3_range()->linear_slop * b2s3_range()->linear_slop;
}

/* `end` continued by one segment away from `inner`: a ghost vertex v3 needs where the file
 * gives none. */
static b2Vec2 b2s3_extrapolated(b2Vec2 end, b2Vec2 inner) {
    b2Vec2 out = {end.x + (end.x - inner.x), end.y + (end.y - inner.y)};
    return out;
}

/* The signed area of a hull, which v3's centroid computation needs positive. */
static float b2s3_hull_area(const b2Hull* hull) {
    float area = 0.0f;
    for (int i = 1; i + 1 < hull->count; ++i) {
        b2Vec2 e1 = b2Sub(hull->points[i], hull->points[0]);
        b2Vec2 e2 = b2Sub(hull->points[i + 1], hull->points[0]);
        area += b2Cross(e1, e2);
    }
    return 0.5f * area;
}

static bool b2s3_make_polygon(b2s3_builder* b, uint32_t index, const b2s_shape* shape,
                              const b2Vec2* points, uint32_t count, b2s3_geometry* out) {
    if (count == 2) {
        if (!b2s3_segment_long_enough(points[0], points[1])) {
            B2S3_REPORT(b, B2S_CODE_DEGENERATE_POLYGON, "shape", index, shape->name,
                        "its two vertices are no farther apart than " B2S3_ENGINE "'s linear "
                        "slop (%g m); shape not created",
                        (double)b2s3_range()->linear_slop);
            return false;
        }
        out->kind = B2S3_SEGMENT;
        out->segment.point1 = points[0];
        out->segment.point2 = points[1];
        return true;
    }
    b2Hull hull = b2ComputeHull(points, (int)count);
    /* v3 asserts that a polygon's area exceeds FLT_EPSILON when it computes the centroid. */
    if (hull.count < 3 || !(b2s3_hull_area(&hull) > 2.0f * FLT_EPSILON)) {
        B2S3_REPORT(b, B2S_CODE_DEGENERATE_POLYGON, "shape", index, shape->name,
                    B2S3_ENGINE " finds no polygon in its vertices (b2ComputeHull welds points "
                    "closer than %g m and drops collinear ones); shape not created",
                    (double)(4.0f * b2s3_range()->linear_slop));
        return false;
    }
    out->kind = B2S3_POLYGON;
    out->polygon = b2MakePolygon(&hull, 0.0f);
    if (shape->centroid_given &&
        b2Distance(b2s3_to_b2(shape->centroid), out->polygon.centroid) >
                                   b2s3_range()->centroid_tolerance) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_SHAPE, "shape", index, shape->name,
                    "its Centroid (%.9g, %.9g) cannot be given to " B2S3_ENGINE ", which uses "
                    "the polygon's own (%.9g, %.9g)",
                    (double)shape->centroid.x, (double)shape->centroid.y,
                    (double)out->polygon.centroid.x, (double)out->polygon.centroid.y);
    }
    return true;
}

static bool b2s3_set_chain_points(b2s3_geometry* out, const b2Vec2* points, int count) {
    out->points = (b2Vec2*)malloc((size_t)count * sizeof(b2Vec2));
    if (out->points == NULL) {
        return false;
    }
    memcpy(out->points, points, (size_t)count * sizeof(b2Vec2));
    out->point_count = count;
    out->kind = B2S3_CHAIN;
    return true;
}

/* An open chain: [prev, vertices..., next], whose first and last segments only guide the
 * ones between; a ghost the file leaves out is extrapolated from its end segment. */
static bool b2s3_make_open_chain(b2s3_builder* b, uint32_t index, const b2s_shape* shape,
                                 const b2Vec2* vertices, uint32_t count, b2s3_geometry* out) {
    b2Vec2* points = (b2Vec2*)malloc(((size_t)count + 2) * sizeof(b2Vec2));
    if (points == NULL) {
        b->list.out_of_memory = true;
        return false;
    }
    points[0] = shape->has_prev_vertex ? b2s3_to_b2(shape->prev_vertex)
                                       : b2s3_extrapolated(vertices[0], vertices[1]);
    memcpy(points + 1, vertices, count * sizeof(b2Vec2));
    points[count + 1] = shape->has_next_vertex
                            ? b2s3_to_b2(shape->next_vertex)
                            : b2s3_extrapolated(vertices[count - 1], vertices[count - 2]);
    bool edge = shape->kind == B2S_SHAPE_KIND_EDGE;
    if (!shape->has_prev_vertex || !shape->has_next_vertex) {
        const char* which = !shape->has_prev_vertex && !shape->has_next_vertex
                                ? "both ghost vertices"
                            : !shape->has_prev_vertex ? (edge ? "Vertex0" : "PrevVertex")
                                                      : (edge ? "Vertex3" : "NextVertex");
        B2S3_REPORT(b, B2S_CODE_LOSSY_SHAPE, "shape", index, shape->name,
                    B2S3_ENGINE "'s chain segments need a ghost vertex at each end: %s "
                    "extrapolated along the end segment",
                    which);
    }
    bool made = b2s3_set_chain_points(out, points, (int)count + 2);
    free(points);
    if (!made) {
        b->list.out_of_memory = true;
    }
    return made;
}

/* A loop: its vertices, from 3 on; where the version needs more points than that, the
 * midpoint of the closing edge, which changes no geometry. */
static bool b2s3_make_loop(b2s3_builder* b, const b2Vec2* vertices, uint32_t count,
                           b2s3_geometry* out) {
    b2Vec2 points[B2S3_MIN_LOOP_POINTS];
    const b2Vec2* used = vertices;
    if (count < B2S3_MIN_LOOP_POINTS) {
        memcpy(points, vertices, count * sizeof(b2Vec2));
        points[count] = b2Lerp(vertices[count - 1], vertices[0], 0.5f);
        used = points;
        count += 1;
    }
    if (!b2s3_set_chain_points(out, used, (int)count)) {
        b->list.out_of_memory = true;
        return false;
    }
    out->is_loop = true;
    return true;
}

/* Every segment v3 will make of the geometry (those a chain's ghosts guide included). */
static bool b2s3_segments_long_enough(const b2s3_geometry* g) {
    if (g->kind == B2S3_SEGMENT) {
        return b2s3_segment_long_enough(g->segment.point1, g->segment.point2);
    }
    if (g->kind != B2S3_CHAIN) {
        return true;
    }
    int segments = g->is_loop ? g->point_count : g->point_count - 1;
    for (int i = 0; i < segments; ++i) {
        if (!b2s3_segment_long_enough(g->points[i], g->points[(i + 1) % g->point_count])) {
            return false;
        }
    }
    return true;
}

static void b2s3_make_shape(b2s3_builder* b, uint32_t index) {
    const b2s_shape* shape = &b->view->shapes[index];
    b2s3_geometry* out = &b->geometries[index];
    uint64_t end = (uint64_t)shape->vertices.first + shape->vertices.count;
    if (shape->kind != B2S_SHAPE_KIND_CIRCLE && end > b->view->vertex_count) {
        B2S3_REPORT(b, B2S_CODE_ID_OUT_OF_RANGE, "shape", index, shape->name,
                    "its vertices lie outside the scene's vertex pool; shape not created");
        return;
    }
    uint32_t count = shape->kind == B2S_SHAPE_KIND_CIRCLE ? 0 : shape->vertices.count;
    const b2s_vec2* vertices = count > 0 ? b->view->vertices + shape->vertices.first : NULL;
    if (shape->kind > B2S_SHAPE_KIND_CHAIN) {
        B2S3_REPORT(b, B2S_CODE_UNKNOWN_TYPE, "shape", index, shape->name,
                    "unknown shape kind %u; shape not created", (unsigned)shape->kind);
        return;
    }
    if (!b2s3_vertex_count_fits(shape, count)) {
        B2S3_REPORT(b, B2S_CODE_BAD_VERTEX_COUNT, "shape", index, shape->name,
                    "%u vertices do not make a " B2S3_ENGINE " shape; shape not created",
                    (unsigned)count);
        return;
    }
    b2s3_check check = b2s3_shape_check(shape, vertices, count);
    if (!b2s3_passed(&check)) {
        b2s3_beyond(b, &check, "shape", index, shape->name, "");
        return;
    }
    b2Vec2* v = (b2Vec2*)malloc((count > 0 ? count : 1) * sizeof(b2Vec2));
    if (v == NULL) {
        b->list.out_of_memory = true;
        return;
    }
    for (uint32_t i = 0; i < count; ++i) {
        v[i] = b2s3_to_b2(vertices[i]);
    }
    bool edge_with_ghosts =
        shape->kind == B2S_SHAPE_KIND_EDGE && (shape->has_prev_vertex || shape->has_next_vertex);
    bool made = false;
    switch (shape->kind) {
    case B2S_SHAPE_KIND_CIRCLE:
        out->kind = B2S3_CIRCLE;
        out->circle.center = b2s3_to_b2(shape->position);
        out->circle.radius = shape->radius;
        made = true;
        break;
    case B2S_SHAPE_KIND_POLYGON: made = b2s3_make_polygon(b, index, shape, v, count, out); break;
    case B2S_SHAPE_KIND_EDGE:
        if (edge_with_ghosts) {
            made = b2s3_make_open_chain(b, index, shape, v, count, out);
        } else {
            out->kind = B2S3_SEGMENT;
            out->segment.point1 = v[0];
            out->segment.point2 = v[1];
            made = true;
        }
        break;
    case B2S_SHAPE_KIND_CHAIN:
        made = shape->is_loop ? b2s3_make_loop(b, v, count, out)
                              : b2s3_make_open_chain(b, index, shape, v, count, out);
        break;
    }
    free(v);
    if (made && !b2s3_segments_long_enough(out)) {
        B2S3_REPORT(b,
                    shape->kind == B2S_SHAPE_KIND_CHAIN ? B2S_CODE_DEGENERATE_CHAIN
                                                        : B2S_CODE_DEGENERATE_EDGE,
                    "shape", index, shape->name,
                    "a segment of it is no longer than " B2S3_ENGINE "'s linear slop (%g m), "
                    "which it refuses; shape not created",
                    (double)b2s3_range()->linear_slop);
        made = false;
    }
    if (!made) {
        free(out->points);
        out->points = NULL;
        out->kind = B2S3_NONE;
    }
}

/* ---- the shapes of one fixture on one body */

static b2s3_check b2s3_fixture_check(const b2s_fixture* fixture) {
    b2s3_check check = {{0}};
    b2s3_magnitude(&check, "Density", fixture->density, b2s3_range()->max_density, "kg/m^2");
    b2s3_magnitude(&check, "Friction", fixture->friction, b2s3_range()->max_friction, "");
    b2s3_magnitude(&check, "Restitution", fixture->restitution, b2s3_range()->max_friction, "");
    if (fixture->density < 0.0f || fixture->friction < 0.0f || fixture->restitution < 0.0f) {
        b2s3_fail(&check, "a negative Density, Friction or Restitution, which " B2S3_ENGINE
                          " asserts against");
    }
    return check;
}

/* Whether fixture `index` of a body will be created: what its mass is made of. */
static bool b2s3_fixture_creatable(const b2s3_builder* b, uint32_t index) {
    if (index >= b->view->fixture_count) {
        return false;
    }
    const b2s_fixture* fixture = &b->view->fixtures[index];
    b2s3_check check = b2s3_fixture_check(fixture);
    return fixture->shape < b->view->shape_count &&
           b->geometries[fixture->shape].kind != B2S3_NONE && b2s3_passed(&check);
}

/* The filter whole: v3's bits are 64, the scene's fewer. */
static b2Filter b2s3_filter(const b2s_filter* filter) {
    b2Filter out = b2DefaultFilter();
    out.categoryBits = filter->category_bits;
    out.maskBits = filter->mask_bits;
    out.groupIndex = filter->group_index;
    return out;
}

/* A chain, the version's way (v31.h, v32.h), with what it loses of the fixture reported. */
static void b2s3_make_chain(b2s3_builder* b, uint32_t index, uint32_t body_index, uint32_t slot,
                            b2BodyId body, const b2ShapeDef* def, const b2s3_geometry* g) {
    const char* loss = b2s3_chain_loss(def);
    if (loss != NULL) {
        B2S3_REPORT(b, B2S_CODE_LOSSY_SHAPE, "fixture", index, b->view->fixtures[index].name,
                    "fixture %u of body %u %s", (unsigned)index, (unsigned)body_index, loss);
    }
    if (!b2s3_create_chain(b->built, &b->chain_capacity, slot, body, def, g->points,
                           g->point_count, g->is_loop)) {
        b->list.out_of_memory = true;
    }
}

static void b2s3_make_fixture(b2s3_builder* b, uint32_t body_index, uint32_t slot,
                              b2BodyId body) {
    uint32_t index = b->view->fixture_ids[slot];
    if (index >= b->view->fixture_count) {
        B2S3_REPORT(b, B2S_CODE_ID_OUT_OF_RANGE, "fixture", index, NULL,
                    "fixture %u of body %u does not exist", (unsigned)index,
                    (unsigned)body_index);
        return;
    }
    const b2s_fixture* fixture = &b->view->fixtures[index];
    if (fixture->shape >= b->view->shape_count ||
        b->geometries[fixture->shape].kind == B2S3_NONE) {
        B2S3_REPORT(b, B2S_CODE_SKIPPED_DEPENDENT, "fixture", index, fixture->name,
                    "fixture %u of body %u names shape %u, which was not created; fixture "
                    "skipped",
                    (unsigned)index, (unsigned)body_index, (unsigned)fixture->shape);
        return;
    }
    b2s3_check check = b2s3_fixture_check(fixture);
    if (!b2s3_passed(&check)) {
        char owner[64];
        snprintf(owner, sizeof owner, "fixture %u of body %u: ", (unsigned)index,
                 (unsigned)body_index);
        b2s3_beyond(b, &check, "fixture", index, fixture->name, owner);
        return;
    }
    const b2s3_geometry* g = &b->geometries[fixture->shape];
    b2ShapeDef def = b2DefaultShapeDef();
    def.density = fixture->density;
    def.material.friction = fixture->friction;
    def.material.restitution = fixture->restitution;
    def.filter = b2s3_filter(&fixture->filter);
    def.isSensor = fixture->is_sensor;
    /* Box2D 2.x's sensors saw every shape; v3's see those with sensor events on. */
    def.enableSensorEvents = true;
    /* One mass update per body, after all its shapes: linear in the shapes, not quadratic. */
    def.updateBodyMass = false;
    switch (g->kind) {
    case B2S3_CIRCLE: b->built->shapes[slot] = b2CreateCircleShape(body, &def, &g->circle); break;
    case B2S3_POLYGON:
        b->built->shapes[slot] = b2CreatePolygonShape(body, &def, &g->polygon);
        break;
    case B2S3_SEGMENT:
        b->built->shapes[slot] = b2CreateSegmentShape(body, &def, &g->segment);
        break;
    case B2S3_CHAIN: b2s3_make_chain(b, index, body_index, slot, body, &def, g); break;
    default: break;
    }
}
