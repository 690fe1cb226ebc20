//! The shapes of a Box2D 2.x plan: each scene shape checked and made once, then given to
//! every fixture that uses it (as the engine clones one shape into each fixture).

use super::made::Made;
use super::shape_mass::MassShape;
use super::world::Mapper;
use crate::error::Code;
use crate::plan::check::Check;
use crate::plan::container::Object;
use crate::plan::math::extrapolated;
use crate::plan::records::{PlanShape, PlanShapeKind};
use crate::rules::{MAX_POLYGON_VERTICES, polygon_hull};
use crate::scene::{Filter, Fixture, Shape, ShapeKind, Str, Vec2};

/// The 16 filter bits Box2D 2.x holds (`uint16`); `report_lossy_filters` says where the
/// cut changes what collides.
const LOW_FILTER_BITS: u32 = 0xFFFF;

/// A made shape before its points go to the plan's pool.
struct Geometry {
    kind: PlanShapeKind,
    points: Vec<Vec2>,
    center: Vec2,
    radius: f32,
    mass: MassShape,
}

impl Mapper<'_> {
    pub(super) fn make_shapes(&mut self) {
        self.shapes = (0..self.scene.shapes().len()).map(|i| self.make_shape(i as u32)).collect();
    }

    fn make_shape(&mut self, index: u32) -> Option<Made> {
        let shape = &self.scene.shapes()[index as usize];
        let Some(points) = self.scene.vertex_pool().get(shape.vertices.indices()) else {
            self.report(
                Code::IdOutOfRange,
                Object::Shape,
                index,
                shape.name,
                format_args!("its vertices lie outside the scene's vertex pool"),
            );
            return None;
        };
        if !vertex_count_fits(shape, points.len()) {
            self.report(
                Code::BadVertexCount,
                Object::Shape,
                index,
                shape.name,
                format_args!("{} vertices do not make a Box2D shape", points.len()),
            );
            return None;
        }
        let check = shape_check(self.check(), shape, points, self.range.max_length);
        if !self.within_range(&check, Object::Shape, index, shape.name, "") {
            return None;
        }
        let made: Geometry = match ShapeKind::try_from(shape.kind) {
            Ok(ShapeKind::Circle) => circle(shape),
            Ok(ShapeKind::Polygon) => polygon(shape, points),
            Ok(ShapeKind::Edge) => edge(shape, points, self.version.ghosts_on_their_own),
            Ok(ShapeKind::Chain) => chain(shape, points, self.version.ghosts_on_their_own),
            Err(kind) => {
                self.report(
                    Code::UnknownType,
                    Object::Shape,
                    index,
                    shape.name,
                    format_args!("unknown shape kind {kind}"),
                );
                return None;
            }
        };
        Some(Made {
            kind: made.kind,
            points: self.plan.push_points(&made.points),
            center: made.center,
            radius: made.radius,
            mass: made.mass,
        })
    }

    pub(super) fn shape_made(&self, fixture: &Fixture) -> bool {
        matches!(self.shapes.get(fixture.shape as usize), Some(Some(_)))
    }

    /// Whether `make_fixture` will create fixture `index`.
    pub(super) fn fixture_creatable(&self, index: u32) -> bool {
        self.scene
            .fixtures()
            .get(index as usize)
            .is_some_and(|fixture| self.shape_made(fixture) && self.fixture_check(fixture).passed())
    }

    /// The plan shape of fixture `index` in the pool's entry `slot` of body `body`, or
    /// None (reported) where it is not created.
    pub(super) fn make_fixture(&mut self, body: u32, slot: u32, index: u32) -> Option<PlanShape> {
        // Only a report needs it.
        let owner = format_args!("fixture {index} of body {body}");
        let Some(fixture) = self.scene.fixtures().get(index as usize) else {
            self.report(
                Code::IdOutOfRange,
                Object::Fixture,
                index,
                Str::NULL,
                format_args!("{owner} does not exist"),
            );
            return None;
        };
        let Some(Some(made)) = self.shapes.get(fixture.shape as usize) else {
            self.report(
                Code::SkippedDependent,
                Object::Fixture,
                index,
                fixture.name,
                format_args!(
                    "{owner} names shape {}, which was not created; fixture skipped",
                    fixture.shape
                ),
            );
            return None;
        };
        let check = self.fixture_check(fixture);
        if !check.passed() {
            let owner = format!("{owner}: ");
            self.within_range(&check, Object::Fixture, index, fixture.name, &owner);
            return None;
        }
        Some(PlanShape {
            slot,
            fixture: index,
            shape: fixture.shape,
            kind: made.kind as u32,
            points: made.points,
            center: made.center,
            radius: made.radius,
            density: fixture.density,
            friction: fixture.friction,
            restitution: fixture.restitution,
            filter: Filter {
                category_bits: fixture.filter.category_bits & LOW_FILTER_BITS,
                mask_bits: fixture.filter.mask_bits & LOW_FILTER_BITS,
                ..fixture.filter
            },
            is_sensor: fixture.is_sensor,
        })
    }
}

impl Mapper<'_> {
    fn fixture_check(&self, fixture: &Fixture) -> Check {
        let range = self.range;
        let mut check = self.check();
        check.magnitude("Density", fixture.density, range.max_density, "kg/m^2");
        check.magnitude("Friction", fixture.friction, range.max_friction, "");
        check.magnitude("Restitution", fixture.restitution, range.max_friction, "");
        check
    }
}

fn vertex_count_fits(shape: &Shape, count: usize) -> bool {
    match ShapeKind::try_from(shape.kind) {
        Ok(ShapeKind::Polygon) => (2..=MAX_POLYGON_VERTICES).contains(&count),
        Ok(ShapeKind::Edge) => count == 2,
        Ok(ShapeKind::Chain) => count >= if shape.is_loop { 3 } else { 2 },
        _ => true,
    }
}

/// The points Box2D gets: every vertex, a circle's centre and radius, the centroid and
/// the ghost vertices where they are used.
fn shape_check(mut check: Check, shape: &Shape, points: &[Vec2], length: f32) -> Check {
    let kind = ShapeKind::try_from(shape.kind);
    let edge = kind == Ok(ShapeKind::Edge);
    if kind == Ok(ShapeKind::Circle) {
        check.magnitude("Radius", shape.radius, length, "m");
        check.vector("Position", shape.position, length, "m");
    }
    let name = |i: usize| if edge { format!("Vertex{}", i + 1) } else { format!("Vertex {i}") };
    check.vectors(name, points, length, "m");
    if kind == Ok(ShapeKind::Polygon) && shape.centroid_given {
        check.vector("Centroid", shape.centroid, length, "m");
    }
    let ghosts = edge || (kind == Ok(ShapeKind::Chain) && !shape.is_loop);
    if ghosts && shape.has_prev_vertex {
        check.vector(if edge { "Vertex0" } else { "PrevVertex" }, shape.prev_vertex, length, "m");
    }
    if ghosts && shape.has_next_vertex {
        check.vector(if edge { "Vertex3" } else { "NextVertex" }, shape.next_vertex, length, "m");
    }
    check
}

fn circle(shape: &Shape) -> Geometry {
    Geometry {
        kind: PlanShapeKind::Circle,
        points: Vec::new(),
        center: shape.position,
        radius: shape.radius,
        mass: MassShape::Circle { center: shape.position, radius: shape.radius },
    }
}

fn no_centroid() -> Vec2 {
    Vec2::new(f32::NAN, f32::NAN)
}

/// Two vertices are Box2D 2.1's `SetAsEdge` output: a line segment.
fn polygon(shape: &Shape, points: &[Vec2]) -> Geometry {
    if let [a, b] = *points {
        return segment(vec![a, b], a, b);
    }
    Geometry {
        kind: PlanShapeKind::Polygon,
        points: points.to_vec(),
        center: if shape.centroid_given { shape.centroid } else { no_centroid() },
        radius: 0.0,
        mass: MassShape::Polygon(polygon_hull(points)),
    }
}

fn segment(points: Vec<Vec2>, a: Vec2, b: Vec2) -> Geometry {
    Geometry {
        kind: PlanShapeKind::Segment,
        points,
        center: no_centroid(),
        radius: 0.0,
        mass: MassShape::Edge(a, b),
    }
}

/// A ghost the file gives, else NaN: Box2D 2.3 keeps each ghost on its own.
fn ghost(given: bool, vertex: Vec2) -> Vec2 {
    if given { vertex } else { no_centroid() }
}

/// An edge with both ghosts is one-sided (`SetOneSided`), else two-sided; in 2.3 one with
/// either keeps it (NaN standing for the one it has not).
fn edge(shape: &Shape, points: &[Vec2], ghosts_on_their_own: bool) -> Geometry {
    let (a, b) = (points[0], points[1]);
    if ghosts_on_their_own && (shape.has_prev_vertex || shape.has_next_vertex) {
        let prev = ghost(shape.has_prev_vertex, shape.prev_vertex);
        segment(vec![prev, a, b, ghost(shape.has_next_vertex, shape.next_vertex)], a, b)
    } else if shape.has_prev_vertex && shape.has_next_vertex {
        segment(vec![shape.prev_vertex, a, b, shape.next_vertex], a, b)
    } else {
        segment(vec![a, b], a, b)
    }
}

/// An open chain with its ghosts: in 2.4 each one the file leaves out extrapolated, in 2.3
/// NaN (2.3 keeps only those given).
fn chain(shape: &Shape, points: &[Vec2], ghosts_on_their_own: bool) -> Geometry {
    let made = |kind, points| Geometry {
        kind,
        points,
        center: no_centroid(),
        radius: 0.0,
        mass: MassShape::Chain,
    };
    if shape.is_loop {
        return made(PlanShapeKind::Loop, points.to_vec());
    }
    let n = points.len();
    let (prev, next) = if ghosts_on_their_own {
        (
            ghost(shape.has_prev_vertex, shape.prev_vertex),
            ghost(shape.has_next_vertex, shape.next_vertex),
        )
    } else {
        extrapolated_ghosts(shape, points)
    };
    let mut all = Vec::with_capacity(n + 2);
    all.push(prev);
    all.extend_from_slice(points);
    all.push(next);
    made(PlanShapeKind::Chain, all)
}

/// An open chain's ghosts as 2.4 gets them: the file's, or its end continued.
fn extrapolated_ghosts(shape: &Shape, points: &[Vec2]) -> (Vec2, Vec2) {
    let n = points.len();
    let prev =
        if shape.has_prev_vertex { shape.prev_vertex } else { extrapolated(points[0], points[1]) };
    let next = if shape.has_next_vertex {
        shape.next_vertex
    } else {
        extrapolated(points[n - 1], points[n - 2])
    };
    (prev, next)
}
