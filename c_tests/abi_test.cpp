// Pins the C ABI: the size of every struct of box2scene.h and the offset of every field, as
// the Rust side lays them out (#[repr(C)] in src/scene.rs, src/ffi.rs, src/error.rs,
// src/lib.rs, which asserts some of the same numbers). A layout change, deliberate or not,
// fails this file's compilation. The numbers are the LP64 layout (x86_64, aarch64).
#include <box2scene.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>

#if UINTPTR_MAX == UINT64_MAX

#define PIN_SIZE(type, size) static_assert(sizeof(type) == (size), "sizeof " #type)
#define PIN_AT(type, field, offset)                                                         \
    static_assert(offsetof(type, field) == (offset), "offsetof " #type "." #field)

// Enumerations travel as uint32_t.
PIN_SIZE(b2s_code, 4);
PIN_SIZE(b2s_shape_kind, 4);
PIN_SIZE(b2s_body_kind, 4);
PIN_SIZE(b2s_joint_kind, 4);
PIN_SIZE(b2s_severity, 4);
PIN_SIZE(b2s_str, 8);

PIN_SIZE(b2s_vec2, 8);
PIN_AT(b2s_vec2, x, 0);
PIN_AT(b2s_vec2, y, 4);

PIN_SIZE(b2s_range, 8);
PIN_AT(b2s_range, first, 0);
PIN_AT(b2s_range, count, 4);

PIN_SIZE(b2s_filter, 12);
PIN_AT(b2s_filter, category_bits, 0);
PIN_AT(b2s_filter, mask_bits, 4);
PIN_AT(b2s_filter, group_index, 8);

PIN_SIZE(b2s_shape, 64);
PIN_AT(b2s_shape, name, 0);
PIN_AT(b2s_shape, kind, 8);
PIN_AT(b2s_shape, radius, 12);
PIN_AT(b2s_shape, position, 16);
PIN_AT(b2s_shape, vertices, 24);
PIN_AT(b2s_shape, centroid, 32);
PIN_AT(b2s_shape, prev_vertex, 40);
PIN_AT(b2s_shape, next_vertex, 48);
PIN_AT(b2s_shape, centroid_given, 56);
PIN_AT(b2s_shape, has_prev_vertex, 57);
PIN_AT(b2s_shape, has_next_vertex, 58);
PIN_AT(b2s_shape, is_loop, 59);

PIN_SIZE(b2s_fixture, 48);
PIN_AT(b2s_fixture, name, 0);
PIN_AT(b2s_fixture, shape, 8);
PIN_AT(b2s_fixture, density, 12);
PIN_AT(b2s_fixture, friction, 16);
PIN_AT(b2s_fixture, restitution, 20);
PIN_AT(b2s_fixture, filter, 24);
PIN_AT(b2s_fixture, is_sensor, 36);
PIN_AT(b2s_fixture, user_data, 40);

PIN_SIZE(b2s_working_range, 136);
PIN_AT(b2s_working_range, max_length, 0);
PIN_AT(b2s_working_range, max_violation, 88);
PIN_AT(b2s_working_range, world_max_linear_speed, 104);
PIN_AT(b2s_working_range, linear_slop, 108);
PIN_AT(b2s_working_range, max_revolute_limit, 112);
PIN_AT(b2s_working_range, centroid_tolerance, 116);
PIN_AT(b2s_working_range, name_bytes, 120);
PIN_AT(b2s_working_range, friction_at_anchors, 124);
PIN_AT(b2s_working_range, prismatic_lever_to_b, 125);
PIN_AT(b2s_working_range, max_lever_pinned_distance, 128);
PIN_AT(b2s_working_range, max_lever_violated_wheel, 132);

PIN_SIZE(b2s_mass_data, 20);
PIN_AT(b2s_mass_data, mass, 0);
PIN_AT(b2s_mass_data, center, 4);
PIN_AT(b2s_mass_data, inertia, 12);
PIN_AT(b2s_mass_data, mass_given, 16);
PIN_AT(b2s_mass_data, center_given, 17);
PIN_AT(b2s_mass_data, inertia_given, 18);

PIN_SIZE(b2s_body, 96);
PIN_AT(b2s_body, name, 0);
PIN_AT(b2s_body, kind, 8);
PIN_AT(b2s_body, position, 12);
PIN_AT(b2s_body, angle, 20);
PIN_AT(b2s_body, linear_velocity, 24);
PIN_AT(b2s_body, angular_velocity, 32);
PIN_AT(b2s_body, linear_damping, 36);
PIN_AT(b2s_body, angular_damping, 40);
PIN_AT(b2s_body, gravity_scale, 44);
PIN_AT(b2s_body, inertia_scale, 48);
PIN_AT(b2s_body, mass_data, 52);
PIN_AT(b2s_body, fixtures, 72);
PIN_AT(b2s_body, user_data, 80);
PIN_AT(b2s_body, active, 84);
PIN_AT(b2s_body, allow_sleep, 85);
PIN_AT(b2s_body, awake, 86);
PIN_AT(b2s_body, bullet, 87);
PIN_AT(b2s_body, fixed_rotation, 88);

PIN_SIZE(b2s_joint, 160);
PIN_AT(b2s_joint, name, 0);
PIN_AT(b2s_joint, kind, 8);
PIN_AT(b2s_joint, body_a, 12);
PIN_AT(b2s_joint, body_b, 16);
PIN_AT(b2s_joint, user_data, 20);
PIN_AT(b2s_joint, joint_a, 24);
PIN_AT(b2s_joint, joint_b, 28);
PIN_AT(b2s_joint, local_anchor_a, 32);
PIN_AT(b2s_joint, local_anchor_b, 40);
PIN_AT(b2s_joint, local_axis_a, 48);
PIN_AT(b2s_joint, ground_anchor_a, 56);
PIN_AT(b2s_joint, ground_anchor_b, 64);
PIN_AT(b2s_joint, linear_offset, 72);
PIN_AT(b2s_joint, reference_angle, 80);
PIN_AT(b2s_joint, lower_limit, 84);
PIN_AT(b2s_joint, upper_limit, 88);
PIN_AT(b2s_joint, motor_speed, 92);
PIN_AT(b2s_joint, max_motor_torque, 96);
PIN_AT(b2s_joint, max_motor_force, 100);
PIN_AT(b2s_joint, length, 104);
PIN_AT(b2s_joint, frequency_hz, 108);
PIN_AT(b2s_joint, damping_ratio, 112);
PIN_AT(b2s_joint, length_a, 116);
PIN_AT(b2s_joint, length_b, 120);
PIN_AT(b2s_joint, max_length_a, 124);
PIN_AT(b2s_joint, max_length_b, 128);
PIN_AT(b2s_joint, ratio, 132);
PIN_AT(b2s_joint, max_force, 136);
PIN_AT(b2s_joint, max_torque, 140);
PIN_AT(b2s_joint, max_length, 144);
PIN_AT(b2s_joint, angular_offset, 148);
PIN_AT(b2s_joint, correction_factor, 152);
PIN_AT(b2s_joint, collide_connected, 156);
PIN_AT(b2s_joint, enable_limit, 157);
PIN_AT(b2s_joint, enable_motor, 158);

PIN_SIZE(b2s_user_data, 24);
PIN_AT(b2s_user_data, raw, 0);
PIN_AT(b2s_user_data, type_name, 8);
PIN_AT(b2s_user_data, value, 16);

PIN_SIZE(b2s_diagnostic, 32);
PIN_AT(b2s_diagnostic, message, 0);
PIN_AT(b2s_diagnostic, byte_offset, 8);
PIN_AT(b2s_diagnostic, code, 16);
PIN_AT(b2s_diagnostic, severity, 20);
PIN_AT(b2s_diagnostic, line, 24);
PIN_AT(b2s_diagnostic, column, 28);

PIN_SIZE(b2s_load_options, 40);
PIN_AT(b2s_load_options, max_input_bytes, 0);
PIN_AT(b2s_load_options, max_elements, 8);
PIN_AT(b2s_load_options, max_text_bytes, 16);
PIN_AT(b2s_load_options, max_depth, 24);
PIN_AT(b2s_load_options, max_chain_vertices, 28);
PIN_AT(b2s_load_options, strict, 32);
PIN_AT(b2s_load_options, threads, 36);

PIN_SIZE(b2s_write_options, 12);
PIN_AT(b2s_write_options, all_fields, 0);
PIN_AT(b2s_write_options, threads, 4);
PIN_AT(b2s_write_options, dialect, 8);

static_assert(B2S_ERROR_MESSAGE_SIZE == 256, "B2S_ERROR_MESSAGE_SIZE");
PIN_SIZE(b2s_error, 280);
PIN_AT(b2s_error, code, 0);
PIN_AT(b2s_error, line, 4);
PIN_AT(b2s_error, column, 8);
PIN_AT(b2s_error, byte_offset, 16);
PIN_AT(b2s_error, message, 24);

PIN_SIZE(struct b2s_scene_view, 112);
PIN_AT(struct b2s_scene_view, shapes, 0);
PIN_AT(struct b2s_scene_view, fixtures, 8);
PIN_AT(struct b2s_scene_view, bodies, 16);
PIN_AT(struct b2s_scene_view, joints, 24);
PIN_AT(struct b2s_scene_view, vertices, 32);
PIN_AT(struct b2s_scene_view, fixture_ids, 40);
PIN_AT(struct b2s_scene_view, user_data, 48);
PIN_AT(struct b2s_scene_view, diagnostics, 56);
PIN_AT(struct b2s_scene_view, shape_count, 64);
PIN_AT(struct b2s_scene_view, fixture_count, 68);
PIN_AT(struct b2s_scene_view, body_count, 72);
PIN_AT(struct b2s_scene_view, joint_count, 76);
PIN_AT(struct b2s_scene_view, vertex_count, 80);
PIN_AT(struct b2s_scene_view, fixture_id_count, 84);
PIN_AT(struct b2s_scene_view, user_data_count, 88);
PIN_AT(struct b2s_scene_view, diagnostic_count, 92);
PIN_AT(struct b2s_scene_view, version, 96);
PIN_AT(struct b2s_scene_view, gravity, 100);
PIN_AT(struct b2s_scene_view, gravity_given, 108);

// The null index is part of the ABI too.
static_assert(B2S_NONE == UINT32_MAX, "B2S_NONE");

int main() {
    std::puts("pass abi layout (checked at compile time)");
    return 0;
}

#else

// CTest's SKIP_RETURN_CODE: the numbers above are the 64-bit layout only.
int main() {
    std::puts("skip: the pinned layout is the LP64 one");
    return 77;
}

#endif
