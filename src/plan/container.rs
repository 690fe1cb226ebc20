//! A plan: the records an executor creates, owned together with their points and texts so
//! that a plan needs nothing of the scene it was made from. Engine modules fill it through
//! the few `push_*` and `report` calls below, in the order the executor creates them.

use std::ffi::{CStr, CString};
use std::fmt;

use super::records::{PlanBody, PlanJoint, PlanReport, PlanShape, PlanView};
use crate::error::Code;
use crate::scene::{Range, Str, Vec2};

/// What a report is about: the kind of scene object its index counts in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Object {
    /// The whole world (index 0).
    World,
    /// A scene shape.
    Shape,
    /// A scene fixture.
    Fixture,
    /// A scene body.
    Body,
    /// A scene joint.
    Joint,
}

impl Object {
    /// The name a report gives it, in static storage.
    pub fn name(self) -> &'static CStr {
        match self {
            Object::World => c"world",
            Object::Shape => c"shape",
            Object::Fixture => c"fixture",
            Object::Body => c"body",
            Object::Joint => c"joint",
        }
    }
}

/// Every body, shape and joint one engine version creates for a scene, and the reports of
/// what it cannot hold. Made by [`make`](super::make()); read through its slices or, from C,
/// its [`PlanView`].
#[derive(Debug, Default)]
pub struct Plan {
    records: Records,
    // Each text's bytes stay where they are when this Vec grows: the records' `Str`s
    // point at them for as long as the plan lives.
    texts: Vec<CString>,
    unplaced: bool,
}

impl Plan {
    /// The bodies, in the order to create them.
    pub fn bodies(&self) -> &[PlanBody] {
        &self.records.bodies
    }

    /// The shapes; each body's are the range its `shapes` names.
    pub fn shapes(&self) -> &[PlanShape] {
        &self.records.shapes
    }

    /// The point pool the shapes' `points` ranges index.
    pub fn point_pool(&self) -> &[Vec2] {
        &self.records.points
    }

    /// The points of one shape.
    pub fn points(&self, shape: &PlanShape) -> &[Vec2] {
        self.records.points.get(shape.points.indices()).unwrap_or(&[])
    }

    /// The joints, in the order to create them, after every body.
    pub fn joints(&self) -> &[PlanJoint] {
        &self.records.joints
    }

    /// The reports, in the order the plan met them.
    pub fn reports(&self) -> &[PlanReport] {
        &self.records.reports
    }

    /// Whether the placement was usable; when not, the plan holds only its report.
    pub fn placed(&self) -> bool {
        !self.unplaced
    }

    /// The text of a name or message this plan holds; `None` for NULL or another's.
    pub fn text(&self, s: Str) -> Option<&str> {
        let text = self.texts.iter().find(|t| t.as_ptr() == s.as_ptr())?;
        text.to_str().ok()
    }

    /// The C view of its arrays, valid while the plan lives unchanged.
    pub fn view(&self) -> PlanView {
        let count = |n: usize| u32::try_from(n).expect("a plan holds fewer than 2^32 items");
        PlanView {
            bodies: self.records.bodies.as_ptr(),
            shapes: self.records.shapes.as_ptr(),
            points: self.records.points.as_ptr(),
            joints: self.records.joints.as_ptr(),
            reports: self.records.reports.as_ptr(),
            body_count: count(self.records.bodies.len()),
            shape_count: count(self.records.shapes.len()),
            point_count: count(self.records.points.len()),
            joint_count: count(self.records.joints.len()),
            report_count: count(self.records.reports.len()),
            placed: self.placed(),
        }
    }

    // ---- the builder's side, for the engine modules

    /// An empty plan with room for as many bodies, shapes and joints as a scene may give:
    /// one allocation each, not a doubling series of copies.
    pub(super) fn with_capacity(bodies: usize, shapes: usize, joints: usize) -> Plan {
        Plan {
            records: Records::with_room(bodies, shapes, joints),
            texts: Vec::new(),
            unplaced: false,
        }
    }

    /// Appends a body; its `name` is a text of this plan (see [`Plan::keep`]).
    pub(super) fn push_body(&mut self, body: PlanBody) {
        self.records.bodies.push(body);
    }

    /// The number of shapes so far: where the next body's range starts.
    pub(super) fn shape_count(&self) -> usize {
        self.records.shapes.len()
    }

    /// Appends a shape.
    pub(super) fn push_shape(&mut self, shape: PlanShape) {
        self.records.shapes.push(shape);
    }

    /// Appends points to the pool, returning their range.
    pub(super) fn push_points(&mut self, points: &[Vec2]) -> Range {
        let first = self.records.points.len();
        self.records.points.extend_from_slice(points);
        Range::between(first, self.records.points.len())
    }

    /// Appends a joint.
    pub(super) fn push_joint(&mut self, joint: PlanJoint) {
        self.records.joints.push(joint);
    }

    /// Marks the plan as made for a placement it could not use.
    pub(super) fn set_unplaced(&mut self) {
        self.unplaced = true;
    }

    /// A copy of `text` owned by the plan, as a C string (NULL for `None`). A text with a
    /// NUL in it is cut there, as C reads it.
    pub(super) fn keep(&mut self, text: Option<&str>) -> Str {
        let Some(text) = text else {
            return Str::NULL;
        };
        let bytes = text.as_bytes();
        let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
        let kept = CString::new(&bytes[..end]).expect("cut at the first NUL");
        let s = Str::from_ptr(kept.as_ptr());
        self.texts.push(kept);
        s
    }

    /// Reports what the engine cannot hold about one object; `message` is formatted only
    /// here, once the report is certain.
    pub(crate) fn report(
        &mut self,
        code: Code,
        object: Object,
        index: u32,
        name: Option<&str>,
        message: fmt::Arguments<'_>,
    ) {
        let name = self.keep(name);
        let message = self.keep(Some(&fmt::format(message)));
        let object = Str::from_ptr(object.name().as_ptr());
        self.records.reports.push(PlanReport { code: code as u32, object, index, name, message });
    }
}

/// The records of a plan, apart from its texts.
#[derive(Debug, Default)]
struct Records {
    bodies: Vec<PlanBody>,
    shapes: Vec<PlanShape>,
    points: Vec<Vec2>,
    joints: Vec<PlanJoint>,
    reports: Vec<PlanReport>,
}

impl Records {
    /// Empty records with room for the scene's bodies, shapes and joints.
    fn with_room(bodies: usize, shapes: usize, joints: usize) -> Records {
        Records {
            bodies: Vec::with_capacity(bodies),
            shapes: Vec::with_capacity(shapes),
            points: Vec::new(),
            joints: Vec::with_capacity(joints),
            reports: Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plan_keeps_its_texts_after_their_source_is_gone() {
        let mut plan = Plan::default();
        {
            let name = String::from("wheel");
            plan.report(Code::LossyBody, Object::Body, 3, Some(&name), format_args!("x {}", 1.5));
        }
        // Many more texts: the first ones must not move when the store grows.
        for i in 0..100 {
            plan.report(Code::SkippedJoint, Object::Joint, i, None, format_args!("joint {i}"));
        }
        let first = plan.reports()[0];
        assert_eq!(first.code, Code::LossyBody as u32);
        assert_eq!(first.index, 3);
        assert_eq!(plan.text(first.name), Some("wheel"));
        assert_eq!(plan.text(first.message), Some("x 1.5"));
        assert_eq!(plan.text(plan.reports()[100].message), Some("joint 99"));
        assert!(plan.reports()[100].name.is_null());
        assert_eq!(plan.text(Str::NULL), None);
        assert_eq!(first.object.as_ptr(), c"body".as_ptr());
    }

    #[test]
    fn a_name_with_a_nul_is_kept_up_to_it() {
        let mut plan = Plan::default();
        let s = plan.keep(Some("ab\0cd"));
        assert_eq!(plan.text(s), Some("ab"));
    }

    #[test]
    fn points_come_back_by_their_range_and_the_view_counts_everything() {
        let mut plan = Plan::default();
        let a = plan.push_points(&[Vec2 { x: 1.0, y: 2.0 }]);
        let b = plan.push_points(&[Vec2 { x: 3.0, y: 4.0 }, Vec2 { x: 5.0, y: 6.0 }]);
        assert_eq!((a.first, a.count, b.first, b.count), (0, 1, 1, 2));
        assert_eq!(plan.point_pool().len(), 3);
        let view = plan.view();
        assert_eq!(view.point_count, 3);
        assert_eq!(view.body_count, 0);
        assert!(view.placed);
        plan.set_unplaced();
        assert!(!plan.view().placed);
        assert!(!plan.placed());
    }
}
