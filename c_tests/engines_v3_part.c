/* The Box2D v3 half of fidelity_24_vs_v3 (engines_v3_part.h). */
#include "engines_v3_part.h"

#include "box2d3_support.h"

static bool report_names(const b2s_box2d3_reports* reports, const struct b2s_scene_view* view,
                         uint32_t body) {
    for (uint32_t i = 0; i < reports->count; ++i) {
        const b2s_box2d3_report* r = &reports->items[i];
        if (strcmp(r->object, "body") == 0 && r->index == body) {
            return true;
        }
        if (strcmp(r->object, "joint") == 0 && r->index < view->joint_count &&
            (view->joints[r->index].body_a == body || view->joints[r->index].body_b == body)) {
            return true;
        }
    }
    return false;
}

int v3_bodies_after(const char* xml, int steps, float* out, unsigned char* named, int capacity) {
    b2s_scene* scene = load_text(xml);
    if (scene == NULL) {
        return -1;
    }
    const struct b2s_scene_view* view = b2s_scene_get_view(scene);
    v3_world w = build_v3(scene);
    step_v3(&w, steps);
    int count = (int)w.built->body_count;
    for (int i = 0; i < count && i < capacity; ++i) {
        b2BodyId body = w.built->bodies[i];
        b2Vec2 p = B2_IS_NULL(body) ? (b2Vec2){NAN, NAN} : b2Body_GetPosition(body);
        out[3 * i] = p.x;
        out[3 * i + 1] = p.y;
        out[3 * i + 2] = B2_IS_NULL(body) ? NAN : b2Rot_GetAngle(b2Body_GetRotation(body));
        named[i] = report_names(&w.built->reports, view, (uint32_t)i);
    }
    free_v3(&w);
    b2s_scene_free(scene);
    return count;
}
