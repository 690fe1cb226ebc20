//! What a capture of a built world takes from the level it was built from: the records
//! the held objects name (their Names and UserData where the host gives none), the
//! joints the build skipped, and the place of each joint in the scene's order.

use super::Label;
use crate::plan::PlanJointKind;
use crate::scene::{Body, Fixture, Joint, JointKind, NONE, Scene, Str};

/// The level, or none (a capture of a world the host made).
#[derive(Clone, Copy, Debug)]
pub(super) struct Level<'a> {
    scene: Option<&'a Scene>,
}

impl<'a> Level<'a> {
    pub(super) fn new(scene: Option<&'a Scene>) -> Level<'a> {
        Level { scene }
    }

    /// The level's body `index`, where there is a level and it has one.
    pub(super) fn body(&self, index: u32) -> Option<&'a Body> {
        self.scene?.bodies().get(index as usize)
    }

    /// The level's joint `index`.
    pub(super) fn joint(&self, index: u32) -> Option<&'a Joint> {
        self.scene?.joints().get(index as usize)
    }

    /// The level's fixture that entry `slot` of its fixture ID pool names.
    pub(super) fn fixture(&self, slot: u32) -> Option<&'a Fixture> {
        let scene = self.scene?;
        let index = *scene.fixture_id_pool().get(slot as usize)?;
        scene.fixtures().get(index as usize)
    }

    /// The Name of the shape of the fixture that entry `slot` names.
    pub(super) fn shape_name(&self, slot: u32) -> Option<&'a str> {
        let scene = self.scene?;
        let shape = scene.shapes().get(self.fixture(slot)?.shape as usize)?;
        scene.text(shape.name)
    }

    /// The Name and UserData of a level record (`name`, `user_data` its fields).
    pub(super) fn label(&self, name: Str, user_data: u32) -> Label<'a> {
        let Some(scene) = self.scene else {
            return Label::default();
        };
        let data = scene.user_data_at(user_data);
        Label {
            name: scene.text(name),
            user_data_raw: data.and_then(|d| scene.text(d.raw)),
            user_data_type: data.and_then(|d| scene.text(d.type_name)),
            user_data_value: data.and_then(|d| scene.text(d.value)),
        }
    }

    /// The number of joints the level has (0 without one).
    pub(super) fn joint_count(&self) -> u32 {
        self.scene.map_or(0, |s| s.joints().len() as u32)
    }

    /// Where held joint `created` (the scene joint `record`, `NONE` for the host's) stands
    /// among the joints written: the level's at their index, a gear right after the later
    /// of the joints it couples (a scene takes a gear after them), the host's after every
    /// one of the level's, in creation order.
    pub(super) fn place(&self, record: u32, created: u32) -> u64 {
        let Some(joint) = self.joint(record) else {
            return 2 * u64::from(self.joint_count()) + u64::from(created);
        };
        let mut last = record;
        if joint.kind == JointKind::Gear as u32 {
            for coupled in [joint.joint_a, joint.joint_b] {
                if coupled != NONE && coupled < self.joint_count() {
                    last = last.max(coupled);
                }
            }
        }
        2 * u64::from(last) + u64::from(last > record)
    }
}

/// Whether a held joint's kind is the plan's gear, which names joints.
pub(super) fn is_gear(kind: u32) -> bool {
    kind == PlanJointKind::Gear as u32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Builder;
    use crate::scene::BodyKind;

    /// Two bodies, a revolute joint 0, a gear 1 on joints 0 and 2, a revolute joint 2.
    fn level() -> Scene {
        let mut b = Builder::new();
        let body = crate::scene::Body::new(BodyKind::Dynamic);
        b.add_body(&body, Some("a"), &[]).unwrap();
        b.add_body(&body, None, &[]).unwrap();
        let mut hinge = Joint::new(JointKind::Revolute);
        (hinge.body_a, hinge.body_b) = (0, 1);
        b.add_joint(&hinge, Some("first")).unwrap();
        b.add_joint(&hinge, Some("second")).unwrap();
        let mut gear = Joint::new(JointKind::Gear);
        (gear.body_a, gear.body_b, gear.joint_a, gear.joint_b, gear.ratio) = (0, 1, 0, 1, 1.0);
        b.add_joint(&gear, None).unwrap();
        b.add_joint(&hinge, None).unwrap();
        b.finish()
    }

    #[test]
    fn the_level_s_joints_keep_their_places_and_the_host_s_come_after() {
        let scene = level();
        let level = Level::new(Some(&scene));
        assert_eq!(level.place(0, 7), 0);
        assert_eq!(level.place(1, 0), 2);
        assert_eq!(level.place(2, 0), 4, "a gear after the joints it couples stays in place");
        assert_eq!(level.place(NONE, 0), 8);
        assert_eq!(level.place(NONE, 3), 11);
        assert_eq!(Level::new(None).place(5, 3), 3);
    }

    #[test]
    fn a_level_record_s_label_is_its_name_and_user_data() {
        let scene = level();
        let level = Level::new(Some(&scene));
        let body = level.body(0).unwrap();
        assert_eq!(level.label(body.name, body.user_data).name, Some("a"));
        assert_eq!(level.label(Str::NULL, NONE), Label::default());
        assert!(level.body(2).is_none());
        assert!(level.fixture(0).is_none());
        assert_eq!(Level::new(None).joint_count(), 0);
    }
}
