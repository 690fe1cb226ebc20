//! The rules of values and geometry, a library the reader, the builder and the checks of
//! a whole scene share, not a stage: values that must be finite or not negative, shape
//! geometry (checked when a shape is complete), a joint's own fields, a dynamic body's
//! fixtures, and a world axis turned into a body's frame.
#![forbid(unsafe_code)]

use crate::error::{Code, Finding, Parsed, problem};
use crate::scene::joints;
use crate::scene::{Body, BodyKind, Fixture, Joint, JointKind, Vec2};

/// Box2D's `b2_maxPolygonVertices`.
pub(crate) const MAX_POLYGON_VERTICES: usize = 8;
/// Box2D's `b2_linearSlop` (m).
pub(crate) const LINEAR_SLOP: f32 = 0.005;

/// A geometry check: fine, a warning, or the error, each at the shape's tag `at`.
type Checked = Result<Option<Finding>, Box<Finding>>;

fn sub(a: Vec2, b: Vec2) -> Vec2 {
    Vec2::new(a.x - b.x, a.y - b.y)
}

fn cross(a: Vec2, b: Vec2) -> f32 {
    a.x * b.y - a.y * b.x
}

fn length_squared(a: Vec2) -> f32 {
    a.x * a.x + a.y * a.y
}

/// `value`, unless it is negative (error `negative-value` naming `what`, which is formatted
/// only then).
pub(crate) fn not_negative(what: impl std::fmt::Display, value: f32, at: usize) -> Parsed<f32> {
    if value < 0.0 {
        return Err(problem(
            Code::NegativeValue,
            at,
            format!("{what} is {value}, but it cannot be negative"),
        ));
    }
    Ok(value)
}

/// Every one of `values` (of the element `name`, given by a host) is finite.
pub(crate) fn finite(name: &str, values: &[f32]) -> Parsed<()> {
    if values.iter().all(|v| v.is_finite()) {
        return Ok(());
    }
    Err(problem(Code::NonFiniteFloat, 0, format!("<{name}> is not a finite number")))
}

/// A circle's radius must be positive.
pub fn circle(radius: f32, at: usize) -> Parsed<()> {
    if radius <= 0.0 {
        return Err(problem(
            Code::BadRadius,
            at,
            format!("a circle's <Radius> must be greater than 0, not {radius}"),
        ));
    }
    Ok(())
}

/// A polygon of 2 (a segment) to 8 vertices, judged the way Box2D 2.4.1's
/// `b2PolygonShape::Set` will treat it: points closer than half the linear slop are merged,
/// the convex hull is taken, and a hull of fewer than 3 points or (near) zero area would be
/// silently replaced by a 1x1 box, so it is an error here.
pub fn polygon(vertices: &[Vec2], at: usize) -> Checked {
    match vertices.len() {
        2 => {
            if length_squared(sub(vertices[1], vertices[0])) < LINEAR_SLOP * LINEAR_SLOP {
                return Err(problem(
                    Code::DegeneratePolygon,
                    at,
                    format!(
                        "the two points of this segment polygon are closer than Box2D's linear slop ({LINEAR_SLOP} m)"
                    ),
                ));
            }
            return Ok(None);
        }
        n if !(2..=MAX_POLYGON_VERTICES).contains(&n) => {
            return Err(problem(
                Code::BadVertexCount,
                at,
                format!(
                    "a polygon needs 2 to {MAX_POLYGON_VERTICES} vertices, this one has {}",
                    vertices.len()
                ),
            ));
        }
        _ => {}
    }
    let (mut merged, mut hull) =
        ([Vec2::ZERO; MAX_POLYGON_VERTICES], [0; MAX_POLYGON_VERTICES + 1]);
    let merged = merge_close_points(vertices, &mut merged);
    let hull = convex_hull(merged, &mut hull);
    if hull.len() < 3 || hull_area(merged, hull) <= f32::EPSILON {
        return Err(problem(
            Code::DegeneratePolygon,
            at,
            "the polygon's points are collinear or (nearly) coincide: it has no area, and Box2D would replace it with a 1x1 box",
        ));
    }
    let kept_in_order = merged.len() == vertices.len()
        && hull.len() == vertices.len()
        && is_rotation_of_identity(hull);
    if kept_in_order {
        Ok(None)
    } else {
        Ok(Some(Finding::new(
            Code::PolygonNotConvexCcw,
            at,
            "the polygon's vertices are not convex in counter-clockwise order; Box2D will use their convex hull",
        )))
    }
}

/// The vertices Box2D 2.4.1's `b2PolygonShape::Set` keeps of a polygon's (of 3 to 8): the
/// close points merged, then the convex hull, counter-clockwise from the rightmost (then
/// lowest) point; fewer than 3 where [`polygon`] finds it degenerate.
pub(crate) fn polygon_hull(vertices: &[Vec2]) -> Vec<Vec2> {
    let (mut merged, mut hull) =
        ([Vec2::ZERO; MAX_POLYGON_VERTICES], [0; MAX_POLYGON_VERTICES + 1]);
    let count = vertices.len().min(MAX_POLYGON_VERTICES);
    let merged = merge_close_points(&vertices[..count], &mut merged);
    convex_hull(merged, &mut hull).iter().map(|&i| merged[i]).collect()
}

/// The vertices without those closer than half the linear slop to an earlier one, in
/// `kept` (as long as `vertices`).
fn merge_close_points<'k>(vertices: &[Vec2], kept: &'k mut [Vec2]) -> &'k [Vec2] {
    let weld = 0.5 * LINEAR_SLOP;
    let mut len = 0;
    for &v in vertices {
        if kept[..len].iter().all(|&k| length_squared(sub(v, k)) >= weld * weld) {
            kept[len] = v;
            len += 1;
        }
    }
    &kept[..len]
}

/// Indices of the convex hull, counter-clockwise from the rightmost (then lowest) point:
/// the gift wrapping of Box2D 2.4.1, collinear points dropped. Made in `hull`, which has
/// room for one more index than there are points. The candidate's edge `r` is kept as
/// the candidate changes rather than computed again for every point: the same values,
/// from the same subtractions.
fn convex_hull<'h>(points: &[Vec2], hull: &'h mut [usize]) -> &'h [usize] {
    let rightmost = (0..points.len()).fold(0, |best, i| {
        let (p, b) = (points[i], points[best]);
        if p.x > b.x || (p.x == b.x && p.y < b.y) { i } else { best }
    });
    let mut len = 0;
    let mut current = rightmost;
    loop {
        hull[len] = current;
        len += 1;
        let from = points[current];
        let (mut next, mut r) = (0, sub(points[0], from));
        for (j, &point) in points.iter().enumerate().skip(1) {
            let v = sub(point, from);
            if next == current {
                (next, r) = (j, v);
                continue;
            }
            let c = cross(r, v);
            if c < 0.0 || (c == 0.0 && length_squared(v) > length_squared(r)) {
                (next, r) = (j, v);
            }
        }
        current = next;
        if current == rightmost || len > points.len() {
            return &hull[..len];
        }
    }
}

fn hull_area(points: &[Vec2], hull: &[usize]) -> f32 {
    let origin = points[hull[0]];
    let twice: f32 = hull
        .windows(2)
        .skip(1)
        .map(|w| cross(sub(points[w[0]], origin), sub(points[w[1]], origin)))
        .sum();
    0.5 * twice
}

/// Whether `hull` is 0, 1, ..., n-1 up to a rotation: the input was already its own hull.
fn is_rotation_of_identity(hull: &[usize]) -> bool {
    let n = hull.len();
    hull.iter().enumerate().all(|(i, &h)| h == (hull[0] + i) % n)
}

/// An edge must have length (at least the linear slop).
pub fn edge(vertices: &[Vec2], at: usize) -> Checked {
    if length_squared(sub(vertices[1], vertices[0])) < LINEAR_SLOP * LINEAR_SLOP {
        return Err(problem(
            Code::DegenerateEdge,
            at,
            format!("the edge is shorter than Box2D's linear slop ({LINEAR_SLOP} m)"),
        ));
    }
    Ok(None)
}

/// A chain needs 2 vertices (a loop 3), no two consecutive ones closer than the linear slop.
pub fn chain(vertices: &[Vec2], is_loop: bool, at: usize) -> Checked {
    let least = if is_loop { 3 } else { 2 };
    if vertices.len() < least {
        let what = if is_loop { "loop" } else { "chain" };
        return Err(problem(
            Code::BadVertexCount,
            at,
            format!("a {what} needs at least {least} vertices, this one has {}", vertices.len()),
        ));
    }
    let closing = is_loop.then(|| [vertices[vertices.len() - 1], vertices[0]]);
    let pairs = vertices.windows(2).map(|w| [w[0], w[1]]).chain(closing);
    for (i, [a, b]) in pairs.enumerate() {
        if length_squared(sub(b, a)) < LINEAR_SLOP * LINEAR_SLOP {
            return Err(problem(
                Code::DegenerateChain,
                at,
                format!(
                    "chain vertices {i} and {} are closer than Box2D's linear slop ({LINEAR_SLOP} m)",
                    (i + 1) % vertices.len()
                ),
            ));
        }
    }
    Ok(None)
}

/// An angle in radians that reads as degrees: a whole number beyond a full turn (2 pi)
/// and within one turn in degrees, as `<LowerAngle>-45</LowerAngle>` is. A whole number
/// of radians past a turn is no angle a level is drawn with; larger values are left to
/// the working range. The warning `angle-in-degrees` for the element `name` at `at`, which
/// says what the value would be in radians.
pub(crate) fn angle_in_degrees(
    name: impl std::fmt::Display,
    radians: f32,
    at: usize,
) -> Option<Finding> {
    let magnitude = radians.abs();
    if radians.fract() != 0.0 || magnitude <= std::f32::consts::TAU || magnitude > 360.0 {
        return None;
    }
    let message = format!(
        "<{name}> is {radians}, a whole number beyond a full turn: it is read as radians; \
         as degrees it would be {} rad",
        radians.to_radians()
    );
    Some(Finding::new(Code::AngleInDegrees, at, message))
}

/// The rules one joint can break on its own (its references are checked elsewhere).
pub(crate) fn joint(joint: &Joint, at: usize, body_b_at: usize) -> Parsed<()> {
    if joint.body_a == joint.body_b {
        return Err(problem(
            Code::JointSelfReference,
            body_b_at,
            format!("the joint connects body {} to itself", joint.body_a),
        ));
    }
    let kind = joint.kind();
    if joint.enable_limit && joint.lower_limit > joint.upper_limit {
        let (lower, upper) = match kind {
            Some(JointKind::Revolute) => ("LowerAngle", "UpperAngle"),
            _ => ("LowerTranslation", "UpperTranslation"),
        };
        return Err(problem(
            Code::BadLimit,
            at,
            format!(
                "{lower} {} is above {upper} {} with the limit enabled",
                joint.lower_limit, joint.upper_limit
            ),
        ));
    }
    let has_axis = kind.is_some_and(|kind| joints::AXIAL.contains(kind));
    if has_axis && joint.local_axis_a == Vec2::ZERO {
        return Err(problem(
            Code::ZeroAxis,
            at,
            "<LocalAxisA> is (0, 0): a joint axis needs a direction",
        ));
    }
    if kind == Some(JointKind::Pulley) && joint.ratio <= 0.0 {
        return Err(problem(
            Code::BadRatio,
            at,
            format!("a pulley's <Ratio> must be greater than 0, not {}", joint.ratio),
        ));
    }
    Ok(())
}

/// "A dynamic body that contains a fixture whose density is zero is malformed", unless its
/// MassData gives a mass: why, for the message, when `body` breaks that rule.
pub(crate) fn zero_density(
    body: &Body,
    fixture_ids: &[u32],
    fixtures: &[Fixture],
) -> Option<String> {
    if body.kind() != Some(BodyKind::Dynamic) || body.mass_data.mass_given {
        return None;
    }
    let ids = &fixture_ids[body.fixtures.indices()];
    let f = ids.iter().find(|&&f| fixtures[f as usize].density == 0.0)?;
    Some(format!(
        "has fixture {f} with density 0 and no MassData mass: that fixture adds no mass, and a \
         dynamic body with no mass at all gets mass 0 in Box2D 2.4 (1 in Box2D 2.1)"
    ))
}

/// `world` in the frame of a body turned by `angle`.
pub(crate) fn local_axis(world: Vec2, angle: f32) -> Vec2 {
    let (sin, cos) = (f64::from(angle).sin() as f32, f64::from(angle).cos() as f32);
    Vec2::new(cos * world.x + sin * world.y, -sin * world.x + cos * world.y)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn set_keeps_the_hull_from_the_rightmost_lowest_point_counter_clockwise() {
        let square = [p(-1.0, -1.0), p(-1.0, 1.0), p(1.0, 1.0), p(1.0, -1.0)];
        assert_eq!(
            polygon_hull(&square),
            vec![p(1.0, -1.0), p(1.0, 1.0), p(-1.0, 1.0), p(-1.0, -1.0)]
        );
        let busy = [
            p(0.0, 0.0),
            p(2.0, 0.0),
            p(1.0, 0.0), // on an edge
            p(1.0, 0.5), // inside
            p(2.0, 2.0),
            p(2.001, 2.0), // within half the linear slop of the last
            p(0.0, 2.0),
        ];
        assert_eq!(polygon_hull(&busy), vec![p(2.0, 0.0), p(2.0, 2.0), p(0.0, 2.0), p(0.0, 0.0)]);
        assert!(polygon_hull(&[p(0.0, 0.0), p(1.0, 0.0), p(2.0, 0.0)]).len() < 3);
        assert!(polygon_hull(&[p(0.0, 0.0), p(0.001, 0.0), p(0.0, 0.001)]).len() < 3);
    }

    /// The gift wrapping as it was before it kept the candidate's edge.
    fn old_convex_hull<'h>(points: &[Vec2], hull: &'h mut [usize]) -> &'h [usize] {
        let rightmost = (0..points.len()).fold(0, |best, i| {
            let (p, b) = (points[i], points[best]);
            if p.x > b.x || (p.x == b.x && p.y < b.y) { i } else { best }
        });
        let mut len = 0;
        let mut current = rightmost;
        loop {
            hull[len] = current;
            len += 1;
            let mut next = 0;
            for j in 1..points.len() {
                if next == current {
                    next = j;
                    continue;
                }
                let r = sub(points[next], points[current]);
                let v = sub(points[j], points[current]);
                let c = cross(r, v);
                if c < 0.0 || (c == 0.0 && length_squared(v) > length_squared(r)) {
                    next = j;
                }
            }
            current = next;
            if current == rightmost || len > points.len() {
                return &hull[..len];
            }
        }
    }

    /// The same hull as before on random sets of 1 to 8 points: on a small grid (so that
    /// points coincide, line up and tie for rightmost) and anywhere.
    #[test]
    fn the_hull_is_the_one_it_was() {
        let mut random = crate::Xorshift(0x243F6A8885A308D3);
        let mut next = |n: u64| random.next() % n;
        for round in 0..300_000 {
            let count = 1 + next(MAX_POLYGON_VERTICES as u64) as usize;
            let points: Vec<Vec2> = (0..count)
                .map(|_| match round % 2 {
                    0 => Vec2::new(next(4) as f32, next(4) as f32),
                    _ => Vec2::new(next(2001) as f32 / 1000.0 - 1.0, next(2001) as f32 / 1000.0),
                })
                .collect();
            let (mut new, mut old) = ([0; MAX_POLYGON_VERTICES + 1], [0; MAX_POLYGON_VERTICES + 1]);
            assert_eq!(
                convex_hull(&points, &mut new),
                old_convex_hull(&points, &mut old),
                "{points:?}"
            );
        }
    }
}
