//! The rules a whole scene is held to once its references are resolved: a dynamic body
//! that gets no mass, a joint that starts far from satisfied. Each is a warning at the
//! object's place in the file.

use crate::arena::Arena;
use crate::error::{Code, Finding, Parsed};
use crate::rules::{LINEAR_SLOP, zero_density};
use crate::scene::{Body, Joint, JointKind, Vec2};

/// Warns about every dynamic body that breaks the [`crate::rules::zero_density`] rule.
pub(crate) fn dynamic_bodies_without_mass(arena: &mut Arena) -> Parsed<()> {
    let Arena { scene: s, origins, findings, .. } = arena;
    for (i, (b, at)) in s.bodies.iter().zip(origins.bodies.iter()).enumerate() {
        if let Some(why) = zero_density(b, &s.fixture_ids, &s.fixtures) {
            let warning = Finding::at(Code::DynamicBodyZeroDensity, at, String::new());
            findings.note_worded(warning, || format!("dynamic body {i} {why}"))?;
        }
    }
    Ok(())
}

/// Box2D's `b2_angularSlop` (rad): 2 degrees.
const ANGULAR_SLOP: f64 = 2.0 / 180.0 * std::f64::consts::PI;

/// A body's place as the file gives it: where a point of its frame lies in the world.
struct Frame {
    position: (f64, f64),
    angle: f64,
}

impl Frame {
    fn of(body: &Body) -> Frame {
        Frame { position: wide(body.position), angle: body.angle.into() }
    }

    fn rotated(&self, v: Vec2) -> (f64, f64) {
        let (x, y) = wide(v);
        let (s, c) = self.angle.sin_cos();
        (c * x - s * y, s * x + c * y)
    }

    fn point(&self, local: Vec2) -> (f64, f64) {
        let (x, y) = self.rotated(local);
        (self.position.0 + x, self.position.1 + y)
    }
}

fn wide(v: Vec2) -> (f64, f64) {
    (v.x.into(), v.y.into())
}

fn distance(a: (f64, f64), b: (f64, f64)) -> f64 {
    (b.0 - a.0).hypot(b.1 - a.1)
}

/// How far `value` lies outside [lower, upper].
fn outside(value: f64, lower: f32, upper: f32) -> f64 {
    (f64::from(lower) - value).max(value - f64::from(upper)).max(0.0)
}

/// How far a joint is from satisfied as the file places its bodies: metres along the
/// constraint its kind holds rigidly, and radians. Springs, motors, friction and gears hold
/// nothing in place as they start.
fn violation(j: &Joint, a: &Body, b: &Body) -> (f64, f64) {
    let (fa, fb) = (Frame::of(a), Frame::of(b));
    let (pa, pb) = (fa.point(j.local_anchor_a), fb.point(j.local_anchor_b));
    let relative = fb.angle - fa.angle - f64::from(j.reference_angle);
    let limited = |value: f64| {
        if j.enable_limit { outside(value, j.lower_limit, j.upper_limit) } else { 0.0 }
    };
    let along_axis = || {
        let (ax, ay) = fa.rotated(j.local_axis_a);
        let norm = ax.hypot(ay);
        let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
        ((ax * dy - ay * dx).abs() / norm, (ax * dx + ay * dy) / norm)
    };
    match j.kind() {
        Some(JointKind::Revolute) => (distance(pa, pb), limited(relative)),
        Some(JointKind::Weld) if j.frequency_hz == 0.0 => (distance(pa, pb), relative.abs()),
        Some(JointKind::Weld) => (distance(pa, pb), 0.0),
        Some(JointKind::Prismatic) => {
            let (across, along) = along_axis();
            (across.max(limited(along)), relative.abs())
        }
        Some(JointKind::Line) => {
            let (across, along) = along_axis();
            (across.max(limited(along)), 0.0)
        }
        Some(JointKind::Wheel) => (along_axis().0, 0.0),
        Some(JointKind::Distance) if j.frequency_hz == 0.0 => {
            ((distance(pa, pb) - f64::from(j.length)).abs(), 0.0)
        }
        Some(JointKind::Rope) => ((distance(pa, pb) - f64::from(j.max_length)).max(0.0), 0.0),
        Some(JointKind::Pulley) => {
            let now = distance(wide(j.ground_anchor_a), pa)
                + f64::from(j.ratio) * distance(wide(j.ground_anchor_b), pb);
            let length = f64::from(j.length_a) + f64::from(j.ratio) * f64::from(j.length_b);
            ((now - length).abs(), 0.0)
        }
        _ => (0.0, 0.0),
    }
}

/// Warns about every joint that starts further from satisfied than Box2D's slop: the level
/// is wrong before any engine sees it, and an engine may tear it apart in its first steps.
pub(crate) fn joints_start_satisfied(arena: &mut Arena) -> Parsed<()> {
    let Arena { scene: s, origins, findings, .. } = arena;
    for (i, (j, at)) in s.joints.iter().zip(origins.joints.iter()).enumerate() {
        let (Some(a), Some(b)) = (s.bodies.get(j.body_a as usize), s.bodies.get(j.body_b as usize))
        else {
            continue;
        };
        let (metres, radians) = violation(j, a, b);
        let linear = metres > f64::from(LINEAR_SLOP);
        let angular = radians > ANGULAR_SLOP;
        if !linear && !angular {
            continue;
        }
        let words = || {
            let how = match (linear, angular) {
                (true, false) => format!("{metres:.3} m"),
                (false, _) => format!("{radians:.3} rad"),
                (true, true) => format!("{metres:.3} m and {radians:.3} rad"),
            };
            format!(
                "joint {i} starts {how} from satisfied where the file places bodies {} and {}; \
                 an engine pulls them together in its first steps",
                j.body_a, j.body_b
            )
        };
        findings
            .note_worded(Finding::at(Code::JointStartsViolated, at.body_a, String::new()), words)?;
    }
    Ok(())
}
