//! What a picture draws, in metres of the world: each frame's bodies and joints, the paths,
//! the bodies to label and the bounds of it all, before anything is laid out or written.

use super::{Picture, Pose};
use crate::scene::{Body, BodyKind, Joint, JointKind, Scene, ShapeKind, Str, Vec2};

/// A joint's anchor dot is a fifth of the smaller body it joins (`svg` sets the smallest).
const ANCHOR_PER_BODY: f64 = 0.2;

/// A point of the world, in metres: in double precision, so that points of a scene whose
/// coordinates reach the edges of single precision, and their differences, stay finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Point {
    pub(super) x: f64,
    pub(super) y: f64,
}

impl Point {
    pub(super) fn of(v: Vec2) -> Point {
        Point { x: f64::from(v.x), y: f64::from(v.y) }
    }

    pub(super) fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

/// A body's position and rotation, as Box2D's `b2Transform` holds them.
#[derive(Clone, Copy)]
pub(super) struct Placement {
    pub(super) position: Point,
    pub(super) cos: f64,
    pub(super) sin: f64,
}

impl Placement {
    /// None for a pose that is not finite.
    pub(super) fn of(pose: Pose) -> Option<Placement> {
        let position = Point::of(pose.position);
        let angle = f64::from(pose.angle);
        (position.is_finite() && angle.is_finite()).then(|| Placement {
            position,
            cos: angle.cos(),
            sin: angle.sin(),
        })
    }

    /// The world point of a point in body coordinates.
    pub(super) fn apply(self, v: Vec2) -> Point {
        self.at(Point::of(v))
    }

    pub(super) fn at(self, p: Point) -> Point {
        Point {
            x: self.cos * p.x - self.sin * p.y + self.position.x,
            y: self.sin * p.x + self.cos * p.y + self.position.y,
        }
    }
}

/// The smallest box holding every point included.
#[derive(Clone, Copy, Default)]
pub(super) struct Bounds {
    pub(super) corners: Option<(Point, Point)>,
}

impl Bounds {
    pub(super) fn include(&mut self, p: Point) {
        let (lower, upper) = self.corners.get_or_insert((p, p));
        *lower = Point { x: lower.x.min(p.x), y: lower.y.min(p.y) };
        *upper = Point { x: upper.x.max(p.x), y: upper.y.max(p.y) };
    }

    pub(super) fn include_circle(&mut self, centre: Point, radius: f64) {
        self.include(Point { x: centre.x - radius, y: centre.y - radius });
        self.include(Point { x: centre.x + radius, y: centre.y + radius });
    }

    pub(super) fn merge(&mut self, other: Bounds) {
        if let Some((lower, upper)) = other.corners {
            self.include(lower);
            self.include(upper);
        }
    }
}

/// One mark of a shape, in the world.
pub(super) enum Mark {
    Polygon(Vec<Point>),
    /// Open: an edge, a chain, a polygon of two vertices (some viewers refuse an SVG
    /// polygon of two points).
    Polyline(Vec<Point>),
    /// Drawn unfilled: a chain that closes on itself.
    Loop(Vec<Point>),
    /// A circle and the radius along its body's x axis, so that its rotation shows.
    Circle {
        centre: Point,
        radius: f64,
        rim: Point,
    },
}

impl Mark {
    /// The box around the mark.
    pub(super) fn bounds(&self) -> Bounds {
        let mut bounds = Bounds::default();
        match self {
            Mark::Circle { centre, radius, .. } => bounds.include_circle(*centre, *radius),
            Mark::Polygon(points) | Mark::Polyline(points) | Mark::Loop(points) => {
                points.iter().for_each(|&p| bounds.include(p));
            }
        }
        bounds
    }
}

/// A body in one frame: its marks, with the fixture and shape they show as tooltips.
pub(super) struct DrawnBody {
    pub(super) kind: Option<BodyKind>,
    pub(super) class: String,
    pub(super) title: String,
    pub(super) marks: Vec<(Mark, String)>,
    pub(super) bounds: Bounds,
}

/// A joint in one frame: the segments Box2D's debug draw draws, the anchors it marks.
pub(super) struct DrawnJoint {
    pub(super) title: String,
    /// Between the anchors (through a pulley's ground anchors).
    pub(super) segments: Vec<[Point; 2]>,
    /// From each body's origin to its anchor: drawn lighter, since a joint to a large body
    /// (the ground) reaches from far.
    pub(super) arms: Vec<[Point; 2]>,
    pub(super) anchors: [Point; 2],
    /// The anchor dots' radius in metres, or None for the smallest dot.
    pub(super) anchor_radius: Option<f64>,
}

pub(super) struct Frame {
    /// By body index; None where the body's pose is not finite.
    pub(super) bodies: Vec<Option<DrawnBody>>,
    pub(super) joints: Vec<DrawnJoint>,
}

/// Everything a picture holds, in metres, before it is laid out.
pub(super) struct Drawing {
    pub(super) start: Frame,
    pub(super) end: Option<Frame>,
    pub(super) paths: Vec<Vec<Point>>,
    /// Each named body drawn in the last frame: its name and index.
    pub(super) labels: Vec<(String, usize)>,
    pub(super) bounds: Bounds,
}

impl Drawing {
    pub(super) fn new(scene: &Scene, picture: &Picture<'_>) -> Drawing {
        let sizes: Vec<Option<f64>> = scene.bodies().iter().map(|b| body_size(scene, b)).collect();
        let scene_poses: Vec<Pose>;
        let start_poses = match picture.start {
            Some(poses) => poses,
            None => {
                scene_poses = scene
                    .bodies()
                    .iter()
                    .map(|body| Pose { position: body.position, angle: body.angle })
                    .collect();
                &scene_poses
            }
        };
        let start = Frame::draw(scene, start_poses, picture.joints, &sizes);
        let end = picture.end.map(|poses| Frame::draw(scene, poses, picture.joints, &sizes));
        let paths = trajectories(picture.trajectories, scene.bodies().len());

        let mut bounds = Bounds::default();
        for frame in std::iter::once(&start).chain(&end) {
            for body in frame.bodies.iter().flatten() {
                bounds.merge(body.bounds);
            }
            for joint in &frame.joints {
                joint
                    .segments
                    .iter()
                    .chain(&joint.arms)
                    .flatten()
                    .chain(&joint.anchors)
                    .for_each(|&p| bounds.include(p));
            }
        }
        paths.iter().flatten().for_each(|&p| bounds.include(p));

        // Each named body is labelled where it is drawn last.
        let last = end.as_ref().unwrap_or(&start);
        let labels = scene
            .bodies()
            .iter()
            .zip(&last.bodies)
            .enumerate()
            .filter_map(|(index, (body, drawn))| {
                let drawn = drawn.as_ref()?.bounds.corners.is_some();
                Some((scene.text(body.name)?.to_owned(), index)).filter(|_| drawn)
            })
            .collect();
        Drawing { start, end, paths, labels, bounds }
    }

    /// The frame the labels go on: the end, or the start drawn alone.
    pub(super) fn last(&self) -> &Frame {
        self.end.as_ref().unwrap_or(&self.start)
    }
}

impl Frame {
    pub(super) fn draw(
        scene: &Scene,
        poses: &[Pose],
        created: Option<&[bool]>,
        sizes: &[Option<f64>],
    ) -> Frame {
        let placements: Vec<Option<Placement>> = poses.iter().map(|&p| Placement::of(p)).collect();
        let bodies = scene.bodies().iter().zip(&placements).enumerate();
        let bodies = bodies
            .map(|(index, (body, place))| place.map(|place| draw_body(scene, index, body, place)));
        let mut frame = Frame { bodies: bodies.collect(), joints: Vec::new() };
        for (index, joint) in scene.joints().iter().enumerate() {
            if created.is_some_and(|created| !created[index]) {
                continue;
            }
            frame.joints.extend(draw_joint(scene, index, joint, &placements, sizes));
        }
        frame
    }
}

pub(super) fn draw_body(scene: &Scene, index: usize, body: &Body, place: Placement) -> DrawnBody {
    let kind = body.kind();
    let class = kind.map_or_else(|| body.kind.to_string(), |k| k.name().to_owned());
    let title = format!("{} ({class})", label(scene, "body", index, body.name));
    let mut drawn = DrawnBody { kind, class, title, marks: Vec::new(), bounds: Bounds::default() };
    for &fixture_index in scene.body_fixtures(body) {
        let Some(fixture) = scene.fixtures().get(fixture_index as usize) else { continue };
        let Some(shape) = scene.shapes().get(fixture.shape as usize) else { continue };
        let title = format!(
            "{}, {}",
            label(scene, "fixture", fixture_index as usize, fixture.name),
            label(scene, "shape", fixture.shape as usize, shape.name)
        );
        let points: Vec<Point> = scene.vertices(shape).iter().map(|&v| place.apply(v)).collect();
        let mark = match shape.kind() {
            Some(ShapeKind::Circle) => {
                let centre = place.apply(shape.position);
                let radius = f64::from(shape.radius);
                let local = Point::of(shape.position);
                let rim = place.at(Point { x: local.x + radius, y: local.y });
                Mark::Circle { centre, radius, rim }
            }
            Some(ShapeKind::Polygon) if points.len() < 3 => Mark::Polyline(points),
            Some(ShapeKind::Polygon) => Mark::Polygon(points),
            Some(ShapeKind::Chain) if shape.is_loop => Mark::Loop(points),
            Some(ShapeKind::Edge | ShapeKind::Chain) => Mark::Polyline(points),
            None => continue,
        };
        drawn.bounds.merge(mark.bounds());
        drawn.marks.push((mark, title));
    }
    drawn
}

/// Half the larger side of the box around a body's shapes in its own coordinates; None
/// for a body with no shape.
pub(super) fn body_size(scene: &Scene, body: &Body) -> Option<f64> {
    let mut bounds = Bounds::default();
    for &fixture_index in scene.body_fixtures(body) {
        let Some(fixture) = scene.fixtures().get(fixture_index as usize) else { continue };
        let Some(shape) = scene.shapes().get(fixture.shape as usize) else { continue };
        match shape.kind() {
            Some(ShapeKind::Circle) => {
                bounds.include_circle(Point::of(shape.position), f64::from(shape.radius))
            }
            _ => scene.vertices(shape).iter().for_each(|&v| bounds.include(Point::of(v))),
        }
    }
    let (lower, upper) = bounds.corners?;
    Some((upper.x - lower.x).max(upper.y - lower.y) / 2.0)
}

/// None when a body it names is not in the scene (a loaded scene never has such a joint)
/// or is not drawn in this frame.
pub(super) fn draw_joint(
    scene: &Scene,
    index: usize,
    joint: &Joint,
    placements: &[Option<Placement>],
    sizes: &[Option<f64>],
) -> Option<DrawnJoint> {
    let (a, b) = (joint.body_a as usize, joint.body_b as usize);
    let (place_a, place_b) = ((*placements.get(a)?)?, (*placements.get(b)?)?);
    let anchor_a = place_a.apply(joint.local_anchor_a);
    let anchor_b = place_b.apply(joint.local_anchor_b);
    let kind = joint.kind();
    // As b2World::DrawJoint (Box2D 2.4) draws each kind.
    let (segments, arms) = match kind {
        Some(JointKind::Distance) => (vec![[anchor_a, anchor_b]], vec![]),
        Some(JointKind::Pulley) => {
            let (ground_a, ground_b) =
                (Point::of(joint.ground_anchor_a), Point::of(joint.ground_anchor_b));
            (vec![[ground_a, anchor_a], [ground_b, anchor_b], [ground_a, ground_b]], vec![])
        }
        _ => (
            vec![[anchor_a, anchor_b]],
            vec![[place_a.position, anchor_a], [place_b.position, anchor_b]],
        ),
    };
    let smaller = [sizes.get(a), sizes.get(b)]
        .into_iter()
        .filter_map(|size| size.copied().flatten())
        .filter(|size| *size > 0.0)
        .reduce(f64::min);
    let kind = kind.map_or_else(|| joint.kind.to_string(), |k| k.name().to_owned());
    Some(DrawnJoint {
        title: format!("{} ({kind})", label(scene, "joint", index, joint.name)),
        segments,
        arms,
        anchors: [anchor_a, anchor_b],
        anchor_radius: smaller.map(|size| size * ANCHOR_PER_BODY),
    })
}

/// Each body's path: its finite points, split where one is not, each piece of two or more
/// points that do not all coincide.
pub(super) fn trajectories(points: &[Vec2], bodies: usize) -> Vec<Vec<Point>> {
    let mut paths = Vec::new();
    for body in 0..bodies {
        let samples: Vec<Point> =
            points.iter().skip(body).step_by(bodies).map(|&v| Point::of(v)).collect();
        for piece in samples.split(|point| !point.is_finite()) {
            if piece.iter().any(|point| *point != piece[0]) {
                paths.push(piece.to_vec());
            }
        }
    }
    paths
}
/// `body 3 "Crate"`, or `body 3` when it has no name.
pub(super) fn label(scene: &Scene, what: &str, index: usize, name: Str) -> String {
    match scene.text(name) {
        Some(name) => format!("{what} {index} \"{name}\""),
        None => format!("{what} {index}"),
    }
}
