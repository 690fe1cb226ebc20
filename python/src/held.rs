//! A live world read by a Python builder, turned into a scene by the library: the builders
//! read their engine's getters into dicts named as the library's held records
//! (`box2scene::capture`), and every inverse, form and report of the way back is the
//! library's, as it is for the C and C++ adapters.

use box2scene::capture::{self, Held, HeldBody, HeldJoint, HeldLabel, HeldShape, Label};
use box2scene::plan::{
    PlanBody, PlanJoint, PlanJointKind, PlanMass, PlanShape, PlanShapeKind, Rot, Transform,
};
use box2scene::{Filter, NONE, Range, Scene, Str, UserData, Vec2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::plan::ReportTuple;

type Pair = (f32, f32);

/// One record's dict: each field by its name, its default where the builder gives none.
struct Fields<'a, 'py>(&'a Bound<'py, PyDict>);

impl<'py> Fields<'_, 'py> {
    fn get<T: pyo3::conversion::FromPyObjectOwned<'py>>(
        &self,
        name: &str,
        default: T,
    ) -> PyResult<T> {
        match self.0.get_item(name)? {
            Some(v) if !v.is_none() => v.extract::<T>().map_err(Into::into),
            _ => Ok(default),
        }
    }
    fn f32(&self, name: &str) -> PyResult<f32> {
        self.get(name, 0.0)
    }
    fn vec(&self, name: &str) -> PyResult<Vec2> {
        let (x, y): Pair = self.get(name, (0.0, 0.0))?;
        Ok(Vec2::new(x, y))
    }
    fn flag(&self, name: &str) -> PyResult<bool> {
        self.get(name, false)
    }
    fn index(&self, name: &str) -> PyResult<u32> {
        self.get(name, NONE)
    }
    fn text(&self, name: &str) -> PyResult<Option<String>> {
        self.get(name, None)
    }
    fn rot(&self, name: &str) -> PyResult<Rot> {
        let (c, s): Pair = self.get(name, (1.0, 0.0))?;
        Ok(Rot { c, s })
    }
    fn transform(&self, name: &str) -> PyResult<Transform> {
        let ((x, y), (c, s)): (Pair, Pair) = self.get(name, ((0.0, 0.0), (1.0, 0.0)))?;
        Ok(Transform { p: Vec2::new(x, y), q: Rot { c, s } })
    }
}

/// A label's texts, owned while the capture reads them.
#[derive(Default)]
struct Texts {
    name: Option<String>,
    raw: Option<String>,
    type_name: Option<String>,
    value: Option<String>,
}

impl Texts {
    /// `name` and `user_data` ((raw, type, value), any None) of a record's dict.
    fn of(f: &Fields<'_, '_>) -> PyResult<Texts> {
        let (raw, type_name, value): (Option<String>, Option<String>, Option<String>) =
            f.get("user_data", (None, None, None))?;
        Ok(Texts { name: f.text("name")?, raw, type_name, value })
    }
    fn label(&self) -> Label<'_> {
        Label {
            name: self.name.as_deref(),
            user_data_raw: self.raw.as_deref(),
            user_data_type: self.type_name.as_deref(),
            user_data_value: self.value.as_deref(),
        }
    }
}

const NO_LABEL: HeldLabel = HeldLabel {
    name: Str::NULL,
    user_data: UserData { raw: Str::NULL, type_name: Str::NULL, value: Str::NULL },
};

fn named<T: Copy + TryFrom<u32>>(names: &[(&str, T)], kind: &str) -> PyResult<T> {
    names
        .iter()
        .find(|(n, _)| *n == kind)
        .map(|&(_, k)| k)
        .ok_or_else(|| PyValueError::new_err(format!("no held record kind {kind:?}")))
}

const SHAPE_KINDS: [(&str, PlanShapeKind); 5] = [
    ("circle", PlanShapeKind::Circle),
    ("polygon", PlanShapeKind::Polygon),
    ("segment", PlanShapeKind::Segment),
    ("chain", PlanShapeKind::Chain),
    ("loop", PlanShapeKind::Loop),
];

const JOINT_KINDS: [(&str, PlanJointKind); 10] = [
    ("revolute", PlanJointKind::Revolute),
    ("prismatic", PlanJointKind::Prismatic),
    ("distance", PlanJointKind::Distance),
    ("pulley", PlanJointKind::Pulley),
    ("gear", PlanJointKind::Gear),
    ("wheel", PlanJointKind::Wheel),
    ("weld", PlanJointKind::Weld),
    ("friction", PlanJointKind::Friction),
    ("motor", PlanJointKind::Motor),
    ("rope", PlanJointKind::Rope),
];

/// What the builders read, gathered: the records and, per record, its texts.
#[derive(Default)]
struct Read {
    bodies: Vec<HeldBody>,
    shapes: Vec<HeldShape>,
    points: Vec<Vec2>,
    joints: Vec<HeldJoint>,
    body_texts: Vec<Texts>,
    fixture_texts: Vec<Texts>,
    shape_names: Vec<Option<String>>,
    shape_others: Vec<Option<String>>,
    joint_texts: Vec<Texts>,
    joint_others: Vec<Option<String>>,
}

impl Read {
    fn shape(&mut self, d: &Bound<'_, PyDict>) -> PyResult<()> {
        let f = Fields(d);
        let other = f.text("other")?;
        let kind = match other {
            Some(_) => PlanShapeKind::Circle,
            None => named(&SHAPE_KINDS, &f.get::<String>("kind", String::new())?)?,
        };
        let first = self.points.len() as u32;
        let points: Vec<Pair> = f.get("points", Vec::new())?;
        self.points.extend(points.iter().map(|&(x, y)| Vec2::new(x, y)));
        let shape = PlanShape {
            slot: f.index("slot")?,
            fixture: NONE,
            shape: NONE,
            kind: kind as u32,
            points: Range { first, count: points.len() as u32 },
            center: f.vec("center")?,
            radius: f.f32("radius")?,
            density: f.f32("density")?,
            friction: f.f32("friction")?,
            restitution: f.f32("restitution")?,
            filter: Filter::default(),
            is_sensor: f.flag("is_sensor")?,
        };
        self.shapes.push(HeldShape {
            shape,
            category_bits: f.get("category_bits", 1)?,
            mask_bits: f.get("mask_bits", 0xFFFF)?,
            group_index: f.get("group_index", 0)?,
            restitution_threshold: f.get("restitution_threshold", f32::NAN)?,
            chain: f.index("chain")?,
            other: Str::NULL,
            label: NO_LABEL,
            shape_name: Str::NULL,
        });
        self.fixture_texts.push(Texts::of(&f)?);
        self.shape_names.push(f.text("shape_name")?);
        self.shape_others.push(other);
        Ok(())
    }

    fn body(&mut self, d: &Bound<'_, PyDict>) -> PyResult<()> {
        let f = Fields(d);
        let first = self.shapes.len() as u32;
        let shapes: Vec<Bound<'_, PyDict>> = f.get("shapes", Vec::new())?;
        for s in &shapes {
            self.shape(s)?;
        }
        let body = PlanBody {
            body: f.index("body")?,
            kind: f.get("kind", 0)?,
            position: f.vec("position")?,
            angle: f.f32("angle")?,
            rotation: f.rot("rotation")?,
            linear_velocity: f.vec("linear_velocity")?,
            angular_velocity: f.f32("angular_velocity")?,
            linear_damping: f.f32("linear_damping")?,
            angular_damping: f.f32("angular_damping")?,
            gravity_scale: f.f32("gravity_scale")?,
            name: Str::NULL,
            shapes: Range { first, count: shapes.len() as u32 },
            mass: PlanMass {
                mass: f.f32("mass")?,
                center: f.vec("center")?,
                inertia: f.f32("inertia")?,
            },
            velocity_after_mass: Vec2::default(),
            allow_sleep: f.flag("allow_sleep")?,
            awake: f.flag("awake")?,
            fixed_rotation: f.flag("fixed_rotation")?,
            bullet: f.flag("bullet")?,
            enabled: f.flag("enabled")?,
            apply_mass_from_shapes: false,
            set_mass: false,
            set_velocity: false,
        };
        self.bodies.push(HeldBody { body, label: NO_LABEL });
        self.body_texts.push(Texts::of(&f)?);
        Ok(())
    }

    fn joint(&mut self, d: &Bound<'_, PyDict>) -> PyResult<()> {
        let f = Fields(d);
        let other = f.text("other")?;
        let kind = match other {
            Some(_) => PlanJointKind::Revolute,
            None => named(&JOINT_KINDS, &f.get::<String>("kind", String::new())?)?,
        };
        let joint = PlanJoint {
            joint: f.index("joint")?,
            kind: kind as u32,
            body_a: f.index("body_a")?,
            body_b: f.index("body_b")?,
            joint_a: f.index("joint_a")?,
            joint_b: f.index("joint_b")?,
            anchor_a: f.vec("anchor_a")?,
            anchor_b: f.vec("anchor_b")?,
            axis: f.vec("axis")?,
            reference_angle: f.f32("reference_angle")?,
            frame_a: f.transform("frame_a")?,
            frame_b: f.transform("frame_b")?,
            ground_anchor_a: f.vec("ground_anchor_a")?,
            ground_anchor_b: f.vec("ground_anchor_b")?,
            length_a: f.f32("length_a")?,
            length_b: f.f32("length_b")?,
            ratio: f.f32("ratio")?,
            lower: f.f32("lower")?,
            upper: f.f32("upper")?,
            length: f.f32("length")?,
            min_length: f.f32("min_length")?,
            max_length: f.f32("max_length")?,
            motor_speed: f.f32("motor_speed")?,
            max_motor: f.f32("max_motor")?,
            stiffness: f.f32("stiffness")?,
            damping: f.f32("damping")?,
            hertz: f.f32("hertz")?,
            damping_ratio: f.f32("damping_ratio")?,
            linear_offset: f.vec("linear_offset")?,
            angular_offset: f.f32("angular_offset")?,
            max_force: f.f32("max_force")?,
            max_torque: f.f32("max_torque")?,
            correction_factor: f.f32("correction_factor")?,
            collide_connected: f.flag("collide_connected")?,
            enable_limit: f.flag("enable_limit")?,
            enable_motor: f.flag("enable_motor")?,
            enable_spring: f.flag("enable_spring")?,
        };
        self.joints.push(HeldJoint {
            joint,
            linear_hertz: f.f32("linear_hertz")?,
            linear_damping_ratio: f.f32("linear_damping_ratio")?,
            linear_velocity: f.vec("linear_velocity")?,
            angular_velocity: f.f32("angular_velocity")?,
            max_velocity_force: f.f32("max_velocity_force")?,
            max_velocity_torque: f.f32("max_velocity_torque")?,
            other: Str::NULL,
            label: NO_LABEL,
        });
        self.joint_texts.push(Texts::of(&f)?);
        self.joint_others.push(other);
        Ok(())
    }
}

fn labels(texts: &[Texts]) -> Vec<Label<'_>> {
    texts.iter().map(Texts::label).collect()
}

fn texts(texts: &[Option<String>]) -> Vec<Option<&str>> {
    texts.iter().map(Option::as_deref).collect()
}

/// The scene the library makes of what a builder read from its world, and the reports.
pub fn capture(
    py: Python<'_>,
    engine: box2scene::Engine,
    gravity: Pair,
    bodies: &Bound<'_, PyList>,
    joints: &Bound<'_, PyList>,
    skipped_joints: Vec<u32>,
    level: Option<&Scene>,
) -> PyResult<(Scene, Vec<ReportTuple>)> {
    let mut read = Read::default();
    for body in bodies.iter() {
        read.body(body.cast()?)?;
    }
    for joint in joints.iter() {
        read.joint(joint.cast()?)?;
    }
    let (body_labels, fixture_labels, joint_labels) =
        (labels(&read.body_texts), labels(&read.fixture_texts), labels(&read.joint_texts));
    let (shape_names, shape_others, joint_others) =
        (texts(&read.shape_names), texts(&read.shape_others), texts(&read.joint_others));
    let held = Held {
        engine,
        gravity: Vec2::new(gravity.0, gravity.1),
        bodies: &read.bodies,
        shapes: &read.shapes,
        points: &read.points,
        joints: &read.joints,
        skipped_joints: &skipped_joints,
        body_labels: &body_labels,
        fixture_labels: &fixture_labels,
        shape_names: &shape_names,
        shape_others: &shape_others,
        joint_labels: &joint_labels,
        joint_others: &joint_others,
    };
    let captured = capture::capture(&held, level).map_err(|e| crate::error(py, e))?;
    let reports = crate::plan::reports(&captured.reports);
    Ok((captured.scene, reports))
}
