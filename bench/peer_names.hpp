// Every element name the peers know, looked up case-insensitively (docs/format.md)
// in one hash table.
#pragma once

#include <cstdint>

namespace bench::peer {

enum class Name : uint8_t {
    unknown,
    // the world and its containers
    world, gravity, shapes, fixtures, bodies, joints,
    shape, fixture, body, joint, vertices, vertex, id,
    // shapes
    name, radius, position, centroid,
    // fixtures
    density, friction, restitution, is_sensor, filter_data, category_bits, mask_bits,
    group_index,
    // bodies
    active, allow_sleep, awake, bullet, fixed_rotation, angle, angular_damping,
    angular_velocity, linear_damping, linear_velocity, inertia_scale, gravity_scale,
    mass_data, mass, center, inertia,
    // joints
    body_a, body_b, joint_a, joint_b, collide_connected, local_anchor_a, local_anchor_b,
    local_axis_a, reference_angle, enable_limit, lower_angle, upper_angle,
    lower_translation, upper_translation, enable_motor, motor_speed, max_motor_torque,
    max_motor_force, length, frequency_hz, damping_ratio, ground_anchor_a, ground_anchor_b,
    length_a, length_b, max_length_a, max_length_b, ratio, max_force, max_torque,
    max_length, linear_offset, angular_offset, correction_factor,
    count
};

/// The name of the element `tag` (NUL-terminated, any letter case), `Name::unknown` for
/// one the peer does not read.
Name element_name(const char* tag);

} // namespace bench::peer
