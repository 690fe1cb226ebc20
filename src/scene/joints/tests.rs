use super::*;

fn kinds() -> impl Iterator<Item = JointKind> {
    (0..).map_while(|n| JointKind::try_from(n).ok())
}

fn fields() -> impl Iterator<Item = &'static Field> {
    FIELD_GROUPS.iter().flat_map(|group| group.iter())
}

/// A joint with every field at zero, false or none.
fn blank() -> Joint {
    Joint { joint_a: 0, joint_b: 0, ..Joint::new(Unsupported) }
}

/// Sets the field of `value` to a value no field has by default.
fn mark(joint: &mut Joint, value: Value) {
    match value {
        Value::Vector(at) => *at(joint) = Vec2::new(7.0, 7.0),
        Value::Float(at) | Value::NonNegative(at) => *at(joint) = 7.0,
        Value::Flag(at) => *at(joint) = true,
        Value::JointIndex(at) => *at(joint) = 7,
    }
}

/// Whether the field of `value` holds what [`mark`] sets.
fn is_marked(joint: &mut Joint, value: Value) -> bool {
    match value {
        Value::Vector(at) => *at(joint) == Vec2::new(7.0, 7.0),
        Value::Float(at) | Value::NonNegative(at) => *at(joint) == 7.0,
        Value::Flag(at) => *at(joint),
        Value::JointIndex(at) => *at(joint) == 7,
    }
}

#[test]
fn every_kind_is_in_every_kind_and_no_other() {
    assert_eq!(kinds().count(), KIND_COUNT);
    let mut all = Kinds::EMPTY;
    for kind in kinds() {
        assert!(EVERY_KIND.contains(kind), "{kind:?}");
        all = all.and(of(&[kind]));
    }
    assert_eq!(all, EVERY_KIND);
}

#[test]
fn type_names_are_the_kind_names_capitalised() {
    for kind in kinds() {
        assert_eq!(type_name(kind).to_ascii_lowercase(), kind.name());
    }
}

#[test]
fn each_element_is_in_the_table_once() {
    for (i, element) in ELEMENTS.iter().enumerate() {
        let first = ELEMENTS.iter().position(|e| e.name == element.name);
        assert_eq!(first, Some(i), "{}", element.name);
        assert!(std::ptr::eq(named(element.name).unwrap(), element));
    }
    assert!(named("Name").is_none());
}

#[test]
fn what_is_written_is_read_back_and_fills_a_field() {
    for element in &ELEMENTS {
        for kind in kinds() {
            let name = element.name;
            if element.written_for.contains(kind) {
                assert!(element.read_by.contains(kind), "{name} in {kind:?}");
                assert!(element.field.is_some(), "{name}");
                assert_ne!(kind, Unsupported, "{name}");
            }
            if element.version_2_in.contains(kind) {
                assert!(element.written_for.contains(kind), "{name} in {kind:?}");
                assert!(!VERSION_2_KINDS.contains(kind), "{name} in {kind:?}");
            }
        }
    }
}

#[test]
fn the_rows_written_for_a_kind_are_those_that_say_so_in_order() {
    for kind in kinds() {
        let expected: Vec<&str> =
            ELEMENTS.iter().filter(|e| e.written_for.contains(kind)).map(|e| e.name).collect();
        let written: Vec<&str> = written(kind).iter().map(|e| e.name).collect();
        assert_eq!(written, expected, "{kind:?}");
    }
}

#[test]
fn a_farseer_only_joint_drops_what_it_reads() {
    for element in &ELEMENTS {
        let slot = element.slot(Unsupported);
        assert_eq!(slot.is_some(), element.read_by.contains(Unsupported), "{}", element.name);
        assert!(matches!(slot, None | Some(Slot::Dropped)), "{}", element.name);
    }
}

#[test]
fn every_element_fills_a_field_the_groups_list() {
    for element in &ELEMENTS {
        if let Some(field) = element.field {
            assert!(fields().any(|f| f.name == field.name), "{}", element.name);
        }
    }
}

#[test]
fn the_groups_list_each_field_of_the_record_once() {
    let names: Vec<&str> = fields().map(|f| f.name).collect();
    for (i, name) in names.iter().enumerate() {
        assert!(!names[..i].contains(name), "{name}");
    }
    // No two fields reach the same part of the record.
    for field in fields() {
        let mut marked = blank();
        mark(&mut marked, field.value);
        for other in fields().filter(|f| f.name != field.name) {
            assert!(!is_marked(&mut marked, other.value), "{} {}", field.name, other.name);
        }
    }
    // Every kind-specific field is reached (a field added to the record breaks the
    // pattern below until it is listed).
    let mut joint = blank();
    for field in fields() {
        mark(&mut joint, field.value);
    }
    let v = Vec2::new(7.0, 7.0);
    let Joint {
        name: _,
        kind: _,
        body_a: _,
        body_b: _,
        user_data: _,
        collide_connected: _,
        joint_a,
        joint_b,
        local_anchor_a,
        local_anchor_b,
        local_axis_a,
        ground_anchor_a,
        ground_anchor_b,
        linear_offset,
        reference_angle,
        lower_limit,
        upper_limit,
        motor_speed,
        max_motor_torque,
        max_motor_force,
        length,
        frequency_hz,
        damping_ratio,
        length_a,
        length_b,
        max_length_a,
        max_length_b,
        ratio,
        max_force,
        max_torque,
        max_length,
        angular_offset,
        correction_factor,
        enable_limit,
        enable_motor,
    } = joint;
    assert_eq!([joint_a, joint_b], [7, 7]);
    let vectors = [
        local_anchor_a,
        local_anchor_b,
        local_axis_a,
        ground_anchor_a,
        ground_anchor_b,
        linear_offset,
    ];
    assert_eq!(vectors, [v; 6]);
    let floats = [
        reference_angle,
        lower_limit,
        upper_limit,
        motor_speed,
        max_motor_torque,
        max_motor_force,
        length,
        frequency_hz,
        damping_ratio,
        length_a,
        length_b,
        max_length_a,
        max_length_b,
        ratio,
        max_force,
        max_torque,
        max_length,
        angular_offset,
        correction_factor,
    ];
    assert_eq!(floats, [7.0; 19]);
    assert!(enable_limit && enable_motor);
}

#[test]
fn only_a_soft_weld_needs_version_2_for_its_values() {
    let weld = Joint::new(Weld);
    assert!(!has_version_2_value(&weld, Weld));
    assert!(has_version_2_value(&Joint { frequency_hz: 4.0, ..weld }, Weld));
    assert!(has_version_2_value(&Joint { damping_ratio: -0.0, ..weld }, Weld));
    let distance = Joint { frequency_hz: 4.0, ..Joint::new(Distance) };
    assert!(!has_version_2_value(&distance, Distance));
}
