//! Shapes: a scene shape as v3 geometry, made once whatever the fixtures naming it, and the
//! plan shapes a fixture makes of it on one body.

use super::Mapper;
use super::geometry::{Mass, circle_mass, hull_area, polygon_centroid, polygon_mass};
use super::hull::{MAX_POLYGON_VERTICES, compute_hull};
use super::math::{ZERO, distance, distance_squared, lerp};
use crate::error::Code;
use crate::plan::check::Check;
use crate::plan::container::Object;
use crate::plan::math::extrapolated;
use crate::plan::printf::{G, G9};
use crate::plan::records::{PlanShape, PlanShapeKind};
use crate::scene::{Fixture, Range, Shape, ShapeKind, Vec2};

/// A scene shape as the engine takes it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Geometry {
    pub kind: PlanShapeKind,
    /// Its points in the plan's pool: a polygon's hull, a segment's ends, a chain's points.
    pub points: Range,
    /// A circle's.
    pub center: Vec2,
    pub radius: f32,
}

impl Mapper<'_> {
    pub(super) fn make_shape(&mut self, index: u32) {
        let shape = &self.scene.shapes()[index as usize];
        let circle = shape.kind == ShapeKind::Circle as u32;
        let end = u64::from(shape.vertices.first) + u64::from(shape.vertices.count);
        if !circle && end > self.scene.vertex_pool().len() as u64 {
            self.report(
                Code::IdOutOfRange,
                Object::Shape,
                index,
                shape.name,
                format_args!("its vertices lie outside the scene's vertex pool; shape not created"),
            );
            return;
        }
        let vertices = if circle { &[][..] } else { self.scene.vertices(shape) };
        if shape.kind > ShapeKind::Chain as u32 {
            self.report(
                Code::UnknownType,
                Object::Shape,
                index,
                shape.name,
                format_args!("unknown shape kind {}; shape not created", shape.kind),
            );
            return;
        }
        if !vertex_count_fits(shape, vertices.len()) {
            let name = self.v3.name();
            self.report(
                Code::BadVertexCount,
                Object::Shape,
                index,
                shape.name,
                format_args!(
                    "{} vertices do not make a {name} shape; shape not created",
                    vertices.len()
                ),
            );
            return;
        }
        let check = self.shape_check(shape, vertices);
        if !check.passed() {
            self.beyond(check.problem(), Object::Shape, index, shape.name, "");
            return;
        }
        let Some((kind, points)) = self.shape_points(index, shape, vertices) else {
            return;
        };
        if !self.segments_long_enough(kind, &points) {
            let code = if shape.kind == ShapeKind::Chain as u32 {
                Code::DegenerateChain
            } else {
                Code::DegenerateEdge
            };
            let (name, slop) = (self.v3.name(), self.range.linear_slop);
            self.report(
                code,
                Object::Shape,
                index,
                shape.name,
                format_args!(
                    "a segment of it is no longer than {name}'s linear slop ({} m), which it \
                     refuses; shape not created",
                    G(slop)
                ),
            );
            return;
        }
        let points = self.plan.push_points(&points);
        let (center, radius) = if circle { (shape.position, shape.radius) } else { (ZERO, 0.0) };
        self.geometries[index as usize] = Some(Geometry { kind, points, center, radius });
    }

    fn shape_check(&self, shape: &Shape, points: &[Vec2]) -> Check {
        let (v3, bound) = (self.v3, self.range.max_length);
        let mut check = Check::new(v3.name());
        let edge = shape.kind == ShapeKind::Edge as u32;
        if shape.kind == ShapeKind::Circle as u32 {
            check.magnitude("Radius", shape.radius, bound, "m");
            check.vector("Position", shape.position, bound, "m");
        }
        for (i, &p) in points.iter().enumerate() {
            if !check.passed() {
                break;
            }
            let field = if edge { format!("Vertex{}", i + 1) } else { format!("Vertex {i}") };
            check.vector(&field, p, bound, "m");
        }
        if shape.kind == ShapeKind::Polygon as u32 && shape.centroid_given {
            check.vector("Centroid", shape.centroid, bound, "m");
        }
        let ghosts = edge || (shape.kind == ShapeKind::Chain as u32 && !shape.is_loop);
        if ghosts && shape.has_prev_vertex {
            let field = if edge { "Vertex0" } else { "PrevVertex" };
            check.vector(field, shape.prev_vertex, bound, "m");
        }
        if ghosts && shape.has_next_vertex {
            let field = if edge { "Vertex3" } else { "NextVertex" };
            check.vector(field, shape.next_vertex, bound, "m");
        }
        check
    }

    /// What the shape is made into and its points (none where it was reported instead).
    fn shape_points(
        &mut self,
        index: u32,
        shape: &Shape,
        vertices: &[Vec2],
    ) -> Option<(PlanShapeKind, Vec<Vec2>)> {
        let ghosts = shape.has_prev_vertex || shape.has_next_vertex;
        match ShapeKind::try_from(shape.kind).ok()? {
            ShapeKind::Circle => Some((PlanShapeKind::Circle, Vec::new())),
            ShapeKind::Polygon => self.polygon(index, shape, vertices),
            ShapeKind::Edge if ghosts => Some(self.open_chain(index, shape, vertices)),
            ShapeKind::Edge => Some((PlanShapeKind::Segment, vertices.to_vec())),
            ShapeKind::Chain if shape.is_loop => Some(self.closed_loop(vertices)),
            ShapeKind::Chain => Some(self.open_chain(index, shape, vertices)),
        }
    }

    fn polygon(
        &mut self,
        index: u32,
        shape: &Shape,
        vertices: &[Vec2],
    ) -> Option<(PlanShapeKind, Vec<Vec2>)> {
        let (name, slop) = (self.v3.name(), self.range.linear_slop);
        if vertices.len() == 2 {
            if !self.long_enough(vertices[0], vertices[1]) {
                self.report(
                    Code::DegeneratePolygon,
                    Object::Shape,
                    index,
                    shape.name,
                    format_args!(
                        "its two vertices are no farther apart than {name}'s linear slop ({} \
                         m); shape not created",
                        G(slop)
                    ),
                );
                return None;
            }
            return Some((PlanShapeKind::Segment, vertices.to_vec()));
        }
        let hull = compute_hull(vertices, slop);
        // v3 asserts that a polygon's area exceeds FLT_EPSILON when it computes the centroid.
        if hull.len() < 3 || !(hull_area(&hull) > 2.0 * f32::EPSILON) {
            self.report(
                Code::DegeneratePolygon,
                Object::Shape,
                index,
                shape.name,
                format_args!(
                    "{name} finds no polygon in its vertices (b2ComputeHull welds points \
                     closer than {} m and drops collinear ones); shape not created",
                    G(4.0 * slop)
                ),
            );
            return None;
        }
        let centroid = polygon_centroid(&hull);
        if shape.centroid_given
            && distance(shape.centroid, centroid) > self.range.centroid_tolerance
        {
            let c = shape.centroid;
            self.report(
                Code::LossyShape,
                Object::Shape,
                index,
                shape.name,
                format_args!(
                    "its Centroid ({}, {}) cannot be given to {name}, which uses the polygon's \
                     own ({}, {})",
                    G9(c.x),
                    G9(c.y),
                    G9(centroid.x),
                    G9(centroid.y)
                ),
            );
        }
        Some((PlanShapeKind::Polygon, hull))
    }

    /// An open chain: `[prev, vertices..., next]`, whose first and last segments only guide
    /// the ones between; a ghost the file leaves out is extrapolated from its end segment.
    fn open_chain(
        &mut self,
        index: u32,
        shape: &Shape,
        vertices: &[Vec2],
    ) -> (PlanShapeKind, Vec<Vec2>) {
        let n = vertices.len();
        let mut points = Vec::with_capacity(n + 2);
        points.push(if shape.has_prev_vertex {
            shape.prev_vertex
        } else {
            extrapolated(vertices[0], vertices[1])
        });
        points.extend_from_slice(vertices);
        points.push(if shape.has_next_vertex {
            shape.next_vertex
        } else {
            extrapolated(vertices[n - 1], vertices[n - 2])
        });
        if !shape.has_prev_vertex || !shape.has_next_vertex {
            let edge = shape.kind == ShapeKind::Edge as u32;
            let which = match (shape.has_prev_vertex, shape.has_next_vertex) {
                (false, false) => "both ghost vertices",
                (false, true) if edge => "Vertex0",
                (false, true) => "PrevVertex",
                _ if edge => "Vertex3",
                _ => "NextVertex",
            };
            let name = self.v3.name();
            self.report(
                Code::LossyShape,
                Object::Shape,
                index,
                shape.name,
                format_args!(
                    "{name}'s chain segments need a ghost vertex at each end: {which} \
                     extrapolated along the end segment"
                ),
            );
        }
        (PlanShapeKind::Chain, points)
    }

    /// A loop: its vertices; where the version needs more points than that, the midpoint of
    /// the closing edge, which changes no geometry.
    fn closed_loop(&self, vertices: &[Vec2]) -> (PlanShapeKind, Vec<Vec2>) {
        let mut points = vertices.to_vec();
        if points.len() < self.v3.min_loop_points() {
            points.push(lerp(vertices[vertices.len() - 1], vertices[0], 0.5));
        }
        (PlanShapeKind::Loop, points)
    }

    /// v3 refuses (asserts against) a segment no longer than its linear slop.
    fn long_enough(&self, a: Vec2, b: Vec2) -> bool {
        let slop = self.range.linear_slop;
        distance_squared(a, b) > slop * slop
    }

    /// Every segment v3 makes of the geometry (those a chain's ghosts guide included).
    fn segments_long_enough(&self, kind: PlanShapeKind, points: &[Vec2]) -> bool {
        let n = points.len();
        let segments = match kind {
            PlanShapeKind::Segment | PlanShapeKind::Chain => n - 1,
            PlanShapeKind::Loop => n,
            PlanShapeKind::Circle | PlanShapeKind::Polygon => 0,
        };
        (0..segments).all(|i| self.long_enough(points[i], points[(i + 1) % n]))
    }

    // ---- the shapes of one fixture on one body

    pub(super) fn fixture_check(&self, fixture: &Fixture) -> Check {
        let (v3, r) = (self.v3, self.range);
        let mut check = Check::new(v3.name());
        check.magnitude("Density", fixture.density, r.max_density, "kg/m^2");
        check.magnitude("Friction", fixture.friction, r.max_friction, "");
        check.magnitude("Restitution", fixture.restitution, r.max_friction, "");
        if fixture.density < 0.0 || fixture.friction < 0.0 || fixture.restitution < 0.0 {
            check.fail(format_args!(
                "a negative Density, Friction or Restitution, which {} asserts against",
                v3.name()
            ));
        }
        check
    }

    /// The geometry of fixture `index` where it will be created on a body: what a body's
    /// mass is made of.
    pub(super) fn creatable(&self, index: u32) -> Option<(&Fixture, Geometry)> {
        let fixture = self.scene.fixtures().get(index as usize)?;
        let geometry = (*self.geometries.get(fixture.shape as usize)?)?;
        self.fixture_check(fixture).passed().then_some((fixture, geometry))
    }

    /// A shape's mass at a density, as v3 computes it (none for segments and chains).
    pub(super) fn geometry_mass(&self, g: &Geometry, density: f32) -> Mass {
        match g.kind {
            PlanShapeKind::Circle => circle_mass(self.v3, g.center, g.radius, density),
            PlanShapeKind::Polygon => {
                polygon_mass(self.v3, &self.plan.point_pool()[g.points.indices()], density)
            }
            _ => Mass::default(),
        }
    }

    /// The plan shape of the fixture in fixture ID slot `slot` of body `body`, or its report.
    pub(super) fn make_fixture(&mut self, body: u32, slot: u32) {
        let index = self.scene.fixture_id_pool()[slot as usize];
        let Some(fixture) = self.scene.fixtures().get(index as usize) else {
            self.plan.report(
                Code::IdOutOfRange,
                Object::Fixture,
                index,
                None,
                format_args!("fixture {index} of body {body} does not exist"),
            );
            return;
        };
        let Some(g) = self.geometries.get(fixture.shape as usize).copied().flatten() else {
            self.report(
                Code::SkippedDependent,
                Object::Fixture,
                index,
                fixture.name,
                format_args!(
                    "fixture {index} of body {body} names shape {}, which was not created; \
                     fixture skipped",
                    fixture.shape
                ),
            );
            return;
        };
        let check = self.fixture_check(fixture);
        if !check.passed() {
            let owner = format!("fixture {index} of body {body}: ");
            self.beyond(check.problem(), Object::Fixture, index, fixture.name, &owner);
            return;
        }
        let chain = matches!(g.kind, PlanShapeKind::Chain | PlanShapeKind::Loop);
        let loses_sensor = chain && fixture.is_sensor && self.v3.chain_loses_sensor();
        if loses_sensor {
            self.report(
                Code::LossyShape,
                Object::Fixture,
                index,
                fixture.name,
                format_args!(
                    "fixture {index} of body {body} is a sensor, but Box2D v3's chains have no \
                     sensor form; it was made a solid chain"
                ),
            );
        }
        self.plan.push_shape(PlanShape {
            slot,
            fixture: index,
            shape: fixture.shape,
            kind: g.kind as u32,
            points: g.points,
            center: g.center,
            radius: g.radius,
            density: fixture.density,
            friction: fixture.friction,
            restitution: fixture.restitution,
            filter: fixture.filter,
            is_sensor: fixture.is_sensor && !loses_sensor,
        });
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

#[cfg(test)]
mod tests {
    use super::super::test_support::{messages, plan_of};
    use crate::error::Code;
    use crate::plan::{Engine, PlanShapeKind};
    use crate::scene::Vec2;

    const TRIANGLE_LOOP: &str = "<Shape Type=\"Chain\"><Loop>true</Loop><Vertices><Vertex>0 0</Vertex>\
        <Vertex>2 0</Vertex><Vertex>0 2</Vertex></Vertices></Shape>";
    const ON_A_BODY: (&str, &str) = (
        "<Fixture><Shape>0</Shape></Fixture>",
        "<Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body>",
    );

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2 { x, y }
    }

    #[test]
    fn a_three_vertex_loop_gets_the_closing_midpoint_in_v31_only() {
        let (f, b) = ON_A_BODY;
        let plan = plan_of(Engine::Box2d31, TRIANGLE_LOOP, f, b, "");
        let shape = plan.shapes()[0];
        assert_eq!(shape.kind, PlanShapeKind::Loop as u32);
        assert_eq!(plan.points(&shape), [v(0.0, 0.0), v(2.0, 0.0), v(0.0, 2.0), v(0.0, 1.0)]);
        let plan = plan_of(Engine::Box2d32, TRIANGLE_LOOP, f, b, "");
        assert_eq!(plan.points(&plan.shapes()[0]).len(), 3);
        assert!(plan.reports().is_empty());
    }

    #[test]
    fn an_edge_with_one_ghost_extrapolates_the_other_and_says_which() {
        let (f, b) = ON_A_BODY;
        let edge = "<Shape Type=\"Edge\"><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>\
            <HasVertex0>true</HasVertex0><Vertex0>-1 1</Vertex0></Shape>";
        let plan = plan_of(Engine::Box2d32, edge, f, b, "");
        let shape = plan.shapes()[0];
        assert_eq!(shape.kind, PlanShapeKind::Chain as u32);
        assert_eq!(plan.points(&shape), [v(-1.0, 1.0), v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.0)]);
        assert_eq!(
            messages(&plan),
            [(
                Code::LossyShape as u32,
                "shape",
                0,
                "Box2D v3.2's chain segments need a ghost vertex at each end: Vertex3 \
                 extrapolated along the end segment"
            )]
        );
    }

    #[test]
    fn a_polygon_v3_welds_away_is_reported_and_its_fixture_skipped() {
        // Box2D 2.x holds this triangle; v3 welds points closer than four slops (0.02 m).
        let shapes = "<Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>0.015 0\
            </Vertex><Vertex>0 0.015</Vertex></Vertices></Shape>";
        let fixtures = "<Fixture><Shape>0</Shape></Fixture>";
        let body = "<Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body>";
        let plan = plan_of(Engine::Box2d31, shapes, fixtures, body, "");
        assert!(plan.shapes().is_empty());
        assert_eq!(
            messages(&plan),
            [
                (
                    Code::DegeneratePolygon as u32,
                    "shape",
                    0,
                    "Box2D v3 finds no polygon in its vertices (b2ComputeHull welds points \
                     closer than 0.02 m and drops collinear ones); shape not created"
                ),
                (
                    Code::SkippedDependent as u32,
                    "fixture",
                    0,
                    "fixture 0 of body 0 names shape 0, which was not created; fixture skipped"
                ),
            ]
        );
    }

    #[test]
    fn a_centroid_other_than_the_hulls_is_reported() {
        let (f, b) = ON_A_BODY;
        let square = "<Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>2 0</Vertex>\
            <Vertex>2 2</Vertex><Vertex>0 2</Vertex></Vertices><Centroid>1 1.5</Centroid></Shape>";
        let plan = plan_of(Engine::Box2d31, square, f, b, "");
        assert_eq!(
            messages(&plan),
            [(
                Code::LossyShape as u32,
                "shape",
                0,
                "its Centroid (1, 1.5) cannot be given to Box2D v3, which uses the polygon's \
                 own (1, 1)"
            )]
        );
    }
}
