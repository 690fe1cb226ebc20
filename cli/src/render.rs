//! `render`: the scene as it starts, as SVG, with no Box2D: every shape of every fixture
//! where its body's position and angle put it, each joint's anchors and the link between
//! them, names as tooltips.
//!
//! Coordinates are written in metres, as the scene gives them, and one transform turns y up;
//! the view box is fitted to what is drawn. A scene that reaches near the edges of single
//! precision (finite values a file may hold) is drawn scaled down by a power of two, so that
//! every number written stays finite for the viewers, which compute in single precision.

use std::fmt::Write;

use box2scene::escape::svg_text;
use box2scene::{Body, BodyKind, Joint, JointKind, Scene, Shape, ShapeKind, Str, Vec2};

/// Fill and stroke by body type: the colours of the simulate example's drawings.
fn colours(kind: Option<BodyKind>) -> (&'static str, &'static str) {
    match kind {
        Some(BodyKind::Static) | None => ("#c8c8c8", "#606060"),
        Some(BodyKind::Kinematic) => ("#b8e0b0", "#3a7a30"),
        Some(BodyKind::Dynamic) => ("#a8c8f0", "#2a5a9a"),
    }
}

const JOINT_COLOUR: &str = "#d03030";

/// The drawing's larger side, in pixels, for viewers that size it by its own width and
/// height.
const PIXELS: f64 = 800.0;

/// Lines and anchor dots are sized by the drawing, not in metres, so that they look the
/// same in a 2 m scene and a 2 km one: a line is a thousandth of the larger side (under a
/// pixel at [`PIXELS`]), an anchor's radius a three-hundredth.
const LINE_PER_SIDE: f64 = 1000.0;
const ANCHOR_PER_SIDE: f64 = 300.0;

/// The largest coordinate written: viewers compute in single precision, where the view
/// box's corner plus its size, and the points a transform turns over, must stay finite.
const LARGEST: f64 = 1e36;

pub fn svg(scene: &Scene) -> String {
    // Drawn in metres, then again, scaled down, should the drawing reach past LARGEST.
    let drawn = Canvas::draw(scene, 1.0);
    let view = View::around(&drawn.bounds);
    let scale = view.scale();
    let drawn = if scale == 1.0 { drawn } else { Canvas::draw(scene, scale) };
    let number = |v: f64| (v * scale) as f32;
    let size = view.size();
    let mut svg = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{x} {y} {w} {h}\" \
         width=\"{pw}\" height=\"{ph}\">\n\
         <rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n\
         <g transform=\"scale(1,-1)\" stroke-width=\"{stroke}\" stroke-linejoin=\"round\">\n",
        x = number(view.x),
        y = number(view.y),
        w = number(view.width),
        h = number(view.height),
        pw = (PIXELS * view.width / size) as f32,
        ph = (PIXELS * view.height / size) as f32,
        stroke = number(size / LINE_PER_SIDE),
    );
    svg.push_str(&drawn.bodies);
    svg.push_str(&format!(
        "<g class=\"joints\" fill=\"{JOINT_COLOUR}\" stroke=\"{JOINT_COLOUR}\">\n"
    ));
    let anchor_radius = number(size / ANCHOR_PER_SIDE);
    for link in &drawn.links {
        drawn.draw_link(&mut svg, link, anchor_radius);
    }
    svg.push_str("</g>\n</g>\n</svg>\n");
    svg
}

/// A point of the world, in metres: in double precision, so that points of a scene whose
/// coordinates reach the edges of single precision, and their differences, stay finite.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Point {
    x: f64,
    y: f64,
}

/// The bodies drawn, the joints' links, and the bounds of both, every coordinate written
/// times `scale`.
struct Canvas {
    bodies: String,
    links: Vec<Link>,
    bounds: Bounds,
    scale: f64,
}

impl Canvas {
    fn draw(scene: &Scene, scale: f64) -> Canvas {
        let mut canvas =
            Canvas { bodies: String::new(), links: Vec::new(), bounds: Bounds::default(), scale };
        for (index, body) in scene.bodies().iter().enumerate() {
            canvas.draw_body(scene, index, body);
        }
        canvas.links =
            scene.joints().iter().enumerate().filter_map(|(i, j)| link(scene, i, j)).collect();
        for point in canvas.links.iter().flat_map(|link| &link.points) {
            canvas.bounds.include(*point);
        }
        canvas
    }

    /// A coordinate or a length as written.
    fn number(&self, v: f64) -> f32 {
        (v * self.scale) as f32
    }

    fn point_list(&self, points: &[Point]) -> String {
        let pairs: Vec<String> =
            points.iter().map(|p| format!("{},{}", self.number(p.x), self.number(p.y))).collect();
        pairs.join(" ")
    }

    /// A body's group, coloured by its type, holding the shapes of its fixtures.
    fn draw_body(&mut self, scene: &Scene, index: usize, body: &Body) {
        let kind = body.kind();
        let (fill, stroke) = colours(kind);
        let class = kind.map_or_else(|| body.kind.to_string(), |k| lowercase_name(&k));
        let title = format!("{} ({class})", label(scene, "body", index, body.name));
        let _ = writeln!(
            self.bodies,
            "<g class=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\"><title>{}</title>",
            svg_text(&class),
            svg_text(&title)
        );
        let place = Placement::of(body);
        for &fixture_index in scene.body_fixtures(body) {
            let Some(fixture) = scene.fixtures().get(fixture_index as usize) else { continue };
            let Some(shape) = scene.shapes().get(fixture.shape as usize) else { continue };
            let title = format!(
                "{}, {}",
                label(scene, "fixture", fixture_index as usize, fixture.name),
                label(scene, "shape", fixture.shape as usize, shape.name)
            );
            self.draw_shape(scene, shape, place, &svg_text(&title));
        }
        self.bodies.push_str("</g>\n");
    }

    fn draw_shape(&mut self, scene: &Scene, shape: &Shape, place: Placement, title: &str) {
        let points: Vec<Point> = scene.vertices(shape).iter().map(|&v| place.apply(v)).collect();
        let (element, fill) = match shape.kind() {
            Some(ShapeKind::Circle) => return self.draw_circle(shape, place, title),
            // A two-vertex polygon is a segment; some viewers refuse an SVG polygon of two
            // points.
            Some(ShapeKind::Polygon) if points.len() < 3 => ("polyline", " fill=\"none\""),
            Some(ShapeKind::Polygon) => ("polygon", ""),
            Some(ShapeKind::Chain) if shape.is_loop => ("polygon", " fill=\"none\""),
            Some(ShapeKind::Edge | ShapeKind::Chain) => ("polyline", " fill=\"none\""),
            None => return,
        };
        for &point in &points {
            self.bounds.include(point);
        }
        let _ = writeln!(
            self.bodies,
            "<{element} points=\"{}\"{fill}><title>{title}</title></{element}>",
            self.point_list(&points)
        );
    }

    /// A circle, and a radius along the body's local x axis so that its rotation shows.
    fn draw_circle(&mut self, shape: &Shape, place: Placement, title: &str) {
        let centre = place.apply(shape.position);
        let radius = f64::from(shape.radius);
        let rim = place.along_x(shape.position, radius);
        self.bounds.include(Point { x: centre.x - radius, y: centre.y - radius });
        self.bounds.include(Point { x: centre.x + radius, y: centre.y + radius });
        let n = |v: f64| self.number(v);
        let _ = writeln!(
            self.bodies,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"><title>{title}</title></circle>\n\
             <line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
            n(centre.x),
            n(centre.y),
            n(radius),
            n(centre.x),
            n(centre.y),
            n(rim.x),
            n(rim.y)
        );
    }

    fn draw_link(&self, out: &mut String, link: &Link, anchor_radius: f32) {
        let _ = write!(
            out,
            "<g><title>{}</title><polyline points=\"{}\" fill=\"none\"/>",
            svg_text(&link.title),
            self.point_list(&link.points)
        );
        let ends = [link.points.first(), link.points.last()];
        for anchor in ends.into_iter().flatten() {
            let (x, y) = (self.number(anchor.x), self.number(anchor.y));
            let _ = write!(out, "<circle cx=\"{x}\" cy=\"{y}\" r=\"{anchor_radius}\"/>");
        }
        out.push_str("</g>\n");
    }
}

/// What a joint shows: its anchors in the world, joined by a line (through the ground
/// anchors for a pulley).
struct Link {
    title: String,
    points: Vec<Point>,
}

/// None when a body it names is not in the scene (a loaded scene never has such a joint).
fn link(scene: &Scene, index: usize, joint: &Joint) -> Option<Link> {
    let body_a = scene.bodies().get(joint.body_a as usize)?;
    let body_b = scene.bodies().get(joint.body_b as usize)?;
    let a = Placement::of(body_a).apply(joint.local_anchor_a);
    let b = Placement::of(body_b).apply(joint.local_anchor_b);
    let kind = joint.kind();
    let points = match kind {
        Some(JointKind::Pulley) => {
            vec![a, Point::of(joint.ground_anchor_a), Point::of(joint.ground_anchor_b), b]
        }
        _ => vec![a, b],
    };
    let kind = kind.map_or_else(|| joint.kind.to_string(), |k| lowercase_name(&k));
    let title = format!("{} ({kind})", label(scene, "joint", index, joint.name));
    Some(Link { title, points })
}

impl Point {
    fn of(v: Vec2) -> Point {
        Point { x: f64::from(v.x), y: f64::from(v.y) }
    }
}

/// A body's position and rotation, as Box2D's `b2Transform` holds them.
#[derive(Clone, Copy)]
struct Placement {
    position: Point,
    cos: f64,
    sin: f64,
}

impl Placement {
    fn of(body: &Body) -> Placement {
        let (cos, sin) = (body.angle.cos(), body.angle.sin());
        Placement { position: Point::of(body.position), cos: f64::from(cos), sin: f64::from(sin) }
    }

    /// The world point of a point in body coordinates.
    fn apply(self, v: Vec2) -> Point {
        self.at(Point::of(v))
    }

    /// The world point `length` along the body's x axis from `v`, in body coordinates.
    fn along_x(self, v: Vec2, length: f64) -> Point {
        self.at(Point { x: f64::from(v.x) + length, y: f64::from(v.y) })
    }

    fn at(self, p: Point) -> Point {
        Point {
            x: self.cos * p.x - self.sin * p.y + self.position.x,
            y: self.sin * p.x + self.cos * p.y + self.position.y,
        }
    }
}

/// The smallest box holding every point drawn.
#[derive(Default)]
struct Bounds {
    corners: Option<(Point, Point)>,
}

impl Bounds {
    fn include(&mut self, p: Point) {
        let (lower, upper) = self.corners.get_or_insert((p, p));
        *lower = Point { x: lower.x.min(p.x), y: lower.y.min(p.y) };
        *upper = Point { x: upper.x.max(p.x), y: upper.y.max(p.y) };
    }
}

/// The view box, in SVG's coordinates (y down): the bounds turned over, with a margin of
/// a twentieth of their larger side (1 m around a single point or an empty scene).
struct View {
    x: f64,
    y: f64,
    width: f64,
    height: f64,
}

impl View {
    fn around(bounds: &Bounds) -> View {
        let origin = Point { x: 0.0, y: 0.0 };
        let (lower, upper) = bounds.corners.unwrap_or((origin, origin));
        let (width, height) = (upper.x - lower.x, upper.y - lower.y);
        let larger = width.max(height);
        let margin = if larger > 0.0 { larger / 20.0 } else { 1.0 };
        View {
            x: lower.x - margin,
            y: -(upper.y + margin),
            width: width + 2.0 * margin,
            height: height + 2.0 * margin,
        }
    }

    fn size(&self) -> f64 {
        self.width.max(self.height)
    }

    /// 1, or the power of two that brings every corner of the view within [`LARGEST`].
    fn scale(&self) -> f64 {
        let corners = [self.x, self.y, self.x + self.width, self.y + self.height];
        let extent = corners.into_iter().fold(0.0, |most: f64, v| most.max(v.abs()));
        match extent <= LARGEST {
            true => 1.0,
            false => 2f64.powi(-((extent / LARGEST).log2().ceil() as i32)),
        }
    }
}

/// `body 3 "Crate"`, or `body 3` when it has no name.
fn label(scene: &Scene, what: &str, index: usize, name: Str) -> String {
    match scene.text(name) {
        Some(name) => format!("{what} {index} \"{name}\""),
        None => format!("{what} {index}"),
    }
}

/// `dynamic`, `revolute`: the enumeration's variant name as the format writes it, lower
/// case.
fn lowercase_name(kind: &impl std::fmt::Debug) -> String {
    format!("{kind:?}").to_lowercase()
}
