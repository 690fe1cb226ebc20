#include "scene_checksum.hpp"

#include <cstring>
#include <initializer_list>

namespace bench {
namespace {

/// FNV-1a, fed field by field (never whole records: their padding is not data).
class Sum {
public:
    void bytes(const void* data, size_t size) {
        const unsigned char* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            value_ = (value_ ^ p[i]) * 0x100000001B3u;
        }
    }

    void u64(uint64_t v) { bytes(&v, sizeof v); }
    void u32(uint32_t v) { bytes(&v, sizeof v); }
    void i32(int32_t v) { bytes(&v, sizeof v); }
    void flag(bool v) { u32(v ? 1 : 0); }

    void f32(float v) {
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }

    void vec2(b2s_vec2 v) {
        f32(v.x);
        f32(v.y);
    }

    void range(b2s_range r) {
        u32(r.first);
        u32(r.count);
    }

    /// NULL (absent) and "" (an empty element) differ.
    void str(b2s_str s) {
        if (s == nullptr) {
            u32(UINT32_MAX);
            return;
        }
        size_t length = std::strlen(s);
        u64(length);
        bytes(s, length);
    }

    uint64_t value() const { return value_; }

private:
    uint64_t value_ = 0xCBF29CE484222325u;
};

uint64_t world_sum(const b2s_scene_view& v) {
    Sum sum;
    sum.u32(v.version);
    sum.flag(v.gravity_given);
    if (v.gravity_given) {
        sum.vec2(v.gravity);
    }
    for (uint32_t count : {v.shape_count, v.fixture_count, v.body_count, v.joint_count,
                           v.vertex_count, v.fixture_id_count, v.user_data_count}) {
        sum.u32(count);
    }
    return sum.value();
}

uint64_t shapes_sum(const b2s_scene_view& v) {
    Sum sum;
    for (uint32_t i = 0; i < v.shape_count; ++i) {
        const b2s_shape& s = v.shapes[i];
        sum.str(s.name);
        sum.u32(s.kind);
        sum.f32(s.radius);
        sum.vec2(s.position);
        sum.range(s.vertices);
        sum.vec2(s.centroid);
        sum.vec2(s.prev_vertex);
        sum.vec2(s.next_vertex);
        sum.flag(s.centroid_given);
        sum.flag(s.has_prev_vertex);
        sum.flag(s.has_next_vertex);
        sum.flag(s.is_loop);
    }
    return sum.value();
}

uint64_t fixtures_sum(const b2s_scene_view& v) {
    Sum sum;
    for (uint32_t i = 0; i < v.fixture_count; ++i) {
        const b2s_fixture& f = v.fixtures[i];
        sum.str(f.name);
        sum.u32(f.shape);
        sum.f32(f.density);
        sum.f32(f.friction);
        sum.f32(f.restitution);
        sum.u32(f.filter.category_bits);
        sum.u32(f.filter.mask_bits);
        sum.i32(f.filter.group_index);
        sum.flag(f.is_sensor);
        sum.u32(f.user_data);
    }
    return sum.value();
}

uint64_t bodies_sum(const b2s_scene_view& v) {
    Sum sum;
    for (uint32_t i = 0; i < v.body_count; ++i) {
        const b2s_body& b = v.bodies[i];
        sum.str(b.name);
        sum.u32(b.kind);
        sum.vec2(b.position);
        sum.f32(b.angle);
        sum.vec2(b.linear_velocity);
        sum.f32(b.angular_velocity);
        sum.f32(b.linear_damping);
        sum.f32(b.angular_damping);
        sum.f32(b.gravity_scale);
        sum.f32(b.inertia_scale);
        sum.f32(b.mass_data.mass);
        sum.vec2(b.mass_data.center);
        sum.f32(b.mass_data.inertia);
        sum.flag(b.mass_data.mass_given);
        sum.flag(b.mass_data.center_given);
        sum.flag(b.mass_data.inertia_given);
        sum.range(b.fixtures);
        sum.u32(b.user_data);
        sum.flag(b.active);
        sum.flag(b.allow_sleep);
        sum.flag(b.awake);
        sum.flag(b.bullet);
        sum.flag(b.fixed_rotation);
    }
    return sum.value();
}

uint64_t joints_sum(const b2s_scene_view& v) {
    Sum sum;
    for (uint32_t i = 0; i < v.joint_count; ++i) {
        const b2s_joint& j = v.joints[i];
        sum.str(j.name);
        for (uint32_t index : {j.kind, j.body_a, j.body_b, j.user_data, j.joint_a, j.joint_b}) {
            sum.u32(index);
        }
        for (b2s_vec2 vector : {j.local_anchor_a, j.local_anchor_b, j.local_axis_a,
                                j.ground_anchor_a, j.ground_anchor_b, j.linear_offset}) {
            sum.vec2(vector);
        }
        for (float value :
             {j.reference_angle, j.lower_limit, j.upper_limit, j.motor_speed, j.max_motor_torque,
              j.max_motor_force, j.length, j.frequency_hz, j.damping_ratio, j.length_a, j.length_b,
              j.max_length_a, j.max_length_b, j.ratio, j.max_force, j.max_torque, j.max_length,
              j.angular_offset, j.correction_factor}) {
            sum.f32(value);
        }
        sum.flag(j.collide_connected);
        sum.flag(j.enable_limit);
        sum.flag(j.enable_motor);
    }
    return sum.value();
}

uint64_t vertices_sum(const b2s_scene_view& v) {
    Sum sum;
    for (uint32_t i = 0; i < v.vertex_count; ++i) {
        sum.vec2(v.vertices[i]);
    }
    return sum.value();
}

uint64_t fixture_ids_sum(const b2s_scene_view& v) {
    Sum sum;
    for (uint32_t i = 0; i < v.fixture_id_count; ++i) {
        sum.u32(v.fixture_ids[i]);
    }
    return sum.value();
}

} // namespace

uint64_t SceneChecksum::combined() const {
    Sum sum;
    for (uint64_t part : {world, shapes, fixtures, bodies, joints, vertices, fixture_ids}) {
        sum.u64(part);
    }
    return sum.value();
}

bool SceneChecksum::operator==(const SceneChecksum& other) const {
    return world == other.world && shapes == other.shapes && fixtures == other.fixtures &&
           bodies == other.bodies && joints == other.joints && vertices == other.vertices &&
           fixture_ids == other.fixture_ids;
}

SceneChecksum checksum(const b2s_scene_view& view) {
    return SceneChecksum{world_sum(view),  shapes_sum(view),    fixtures_sum(view),
                         bodies_sum(view), joints_sum(view),    vertices_sum(view),
                         fixture_ids_sum(view)};
}

} // namespace bench
