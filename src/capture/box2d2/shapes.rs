//! A Box2D 2.x shape and its fixture's material read back: the scene shape whose build
//! gives the same shape, and what the format implies that the engine may hold otherwise (a
//! skin radius, the first vertex `b2PolygonShape::Set` picks, a restitution threshold).

use crate::capture::HeldShape;
use crate::capture::world::Say;
use crate::plan::PlanShapeKind;
use crate::plan::box2d2::Version;
use crate::plan::printf::G9;
use crate::rules::{LINEAR_SLOP, polygon_hull};
use crate::scene::{Filter, Fixture, Shape, ShapeKind, Vec2};

/// Box2D 2.x's `b2_polygonRadius`: the skin of every shape but a circle, which the format
/// implies.
const POLYGON_RADIUS: f32 = 2.0 * LINEAR_SLOP;

/// m/s: `b2FixtureDef`'s restitution threshold, the one a built fixture has.
const RESTITUTION_THRESHOLD: f32 = 1.0;

fn same_bits(a: Vec2, b: Vec2) -> bool {
    a.x.to_bits() == b.x.to_bits() && a.y.to_bits() == b.y.to_bits()
}

/// A ghost vertex as the held points give it: 2.3 marks one it has not with NaN.
fn ghost(v: Vec2) -> Option<Vec2> {
    (!v.x.is_nan() || !v.y.is_nan()).then_some(v)
}

/// The scene shape of a held 2.x shape and its vertices; `None` for a kind the plan has
/// not (reported).
pub(crate) fn shape(
    _version: &Version,
    held: &HeldShape,
    points: &[Vec2],
    say: &mut Say,
) -> Option<(Shape, Vec<Vec2>)> {
    let plan = &held.shape;
    let points = points.get(plan.points.indices()).unwrap_or(&[]);
    let Ok(kind) = PlanShapeKind::try_from(plan.kind) else {
        say.report(
            crate::error::Code::UnknownType,
            format_args!("shape kind {} has no Box2Scene form; not written", plan.kind),
        );
        return None;
    };
    let made = match kind {
        PlanShapeKind::Circle => {
            let circle = Shape {
                radius: plan.radius,
                position: plan.center,
                ..Shape::new(ShapeKind::Circle)
            };
            (circle, Vec::new())
        }
        PlanShapeKind::Polygon => polygon(plan.center, points, say),
        PlanShapeKind::Segment => segment(points),
        PlanShapeKind::Chain => chain(points),
        PlanShapeKind::Loop => (looped(), points.to_vec()),
    };
    if kind != PlanShapeKind::Circle && plan.radius != POLYGON_RADIUS {
        say.lossy(format_args!(
            "its skin radius {} is not Box2D's b2_polygonRadius, which the format implies",
            G9(plan.radius)
        ));
    }
    Some(made)
}

/// Box2D keeps the hull; its centroid is always written, so that it comes back exactly
/// even where the host set it.
fn polygon(centroid: Vec2, vertices: &[Vec2], say: &mut Say) -> (Shape, Vec<Vec2>) {
    let rebuilt = polygon_hull(vertices);
    let same = rebuilt.len() == vertices.len()
        && rebuilt.iter().zip(vertices).all(|(&a, &b)| same_bits(a, b));
    if !same {
        say.lossy(format_args!(
            "b2PolygonShape::Set, which build_world uses, orders these vertices from another \
             first vertex (as after SetAsBox): the same polygon, but its contacts may be solved \
             in another order"
        ));
    }
    let shape = Shape { centroid, centroid_given: true, ..Shape::new(ShapeKind::Polygon) };
    (shape, vertices.to_vec())
}

/// A two-sided edge is Version 1's two-vertex polygon; a one-sided one (`[ghost, ends,
/// ghost]`) an Edge with its ghosts.
fn segment(points: &[Vec2]) -> (Shape, Vec<Vec2>) {
    let [prev, a, b, next] = *points else {
        return (Shape::new(ShapeKind::Polygon), points.to_vec());
    };
    (with_ghosts(Shape::new(ShapeKind::Edge), prev, next), vec![a, b])
}

fn with_ghosts(shape: Shape, prev: Vec2, next: Vec2) -> Shape {
    let (prev, next) = (ghost(prev), ghost(next));
    Shape {
        prev_vertex: prev.unwrap_or_default(),
        next_vertex: next.unwrap_or_default(),
        has_prev_vertex: prev.is_some(),
        has_next_vertex: next.is_some(),
        ..shape
    }
}

fn looped() -> Shape {
    Shape { is_loop: true, ..Shape::new(ShapeKind::Chain) }
}

/// A chain as the engine holds it, `[ghost, vertices..., ghost]`: a loop where it has
/// `CreateLoop`'s layout (the first vertex repeated at the end, the ghosts next to the
/// seam, or none: pybox2d's 2.3 leaves them unset), its vertices once each; else an open
/// chain with its ghosts.
fn chain(points: &[Vec2]) -> (Shape, Vec<Vec2>) {
    let Some((&prev, rest)) = points.split_first() else {
        return (Shape::new(ShapeKind::Chain), Vec::new());
    };
    let Some((&next, v)) = rest.split_last() else {
        return (Shape::new(ShapeKind::Chain), Vec::new());
    };
    let n = v.len();
    let unset = ghost(prev).is_none() && ghost(next).is_none();
    let seam = |n: usize| same_bits(prev, v[n - 2]) && same_bits(next, v[1]);
    if n >= 4 && same_bits(v[n - 1], v[0]) && (unset || seam(n)) {
        return (looped(), v[..n - 1].to_vec());
    }
    (with_ghosts(Shape::new(ShapeKind::Chain), prev, next), v.to_vec())
}

/// The scene fixture of a held shape's material; a restitution threshold other than the
/// one a built fixture gets is reported.
pub(crate) fn fixture(_version: &Version, held: &HeldShape, say: &mut Say) -> Fixture {
    let threshold = held.restitution_threshold;
    if !threshold.is_nan() && threshold != RESTITUTION_THRESHOLD {
        say.lossy(format_args!(
            "the format has no restitution threshold; {} becomes Box2D's default",
            G9(threshold)
        ));
    }
    let plan = &held.shape;
    Fixture {
        density: plan.density,
        friction: plan.friction,
        restitution: plan.restitution,
        is_sensor: plan.is_sensor,
        filter: Filter {
            category_bits: held.category_bits as u32,
            mask_bits: held.mask_bits as u32,
            group_index: held.group_index as i16,
        },
        ..Fixture::default()
    }
}
