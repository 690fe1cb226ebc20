//! `render`: the scene as it starts, as SVG, with no Box2D: every shape of every fixture
//! where its body's position and angle put it, each joint's anchors and the link between
//! them, names as tooltips.
//!
//! Coordinates are written in metres, as the scene gives them, and one transform turns y up;
//! the view box is fitted to what is drawn.

use std::fmt::Write;

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
const PIXELS: f32 = 800.0;

/// Lines and anchor dots are sized by the drawing, not in metres, so that they look the
/// same in a 2 m scene and a 2 km one: a line is a thousandth of the larger side (under a
/// pixel at [`PIXELS`]), an anchor's radius a three-hundredth.
const LINE_PER_SIDE: f32 = 1000.0;
const ANCHOR_PER_SIDE: f32 = 300.0;

pub fn svg(scene: &Scene) -> String {
    let mut bounds = Bounds::default();
    let mut bodies = String::new();
    for (index, body) in scene.bodies().iter().enumerate() {
        draw_body(&mut bodies, &mut bounds, scene, index, body);
    }
    let links: Vec<Link> =
        scene.joints().iter().enumerate().filter_map(|(i, j)| link(scene, i, j)).collect();
    for point in links.iter().flat_map(|link| &link.points) {
        bounds.include(*point);
    }
    let view = View::around(&bounds);
    let mut svg = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{x} {y} {w} {h}\" \
         width=\"{pw}\" height=\"{ph}\">\n\
         <rect x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n\
         <g transform=\"scale(1,-1)\" stroke-width=\"{stroke}\" stroke-linejoin=\"round\">\n",
        x = view.x,
        y = view.y,
        w = view.width,
        h = view.height,
        pw = PIXELS * view.width / view.size(),
        ph = PIXELS * view.height / view.size(),
        stroke = view.size() / LINE_PER_SIDE,
    );
    svg.push_str(&bodies);
    svg.push_str(&format!(
        "<g class=\"joints\" fill=\"{JOINT_COLOUR}\" stroke=\"{JOINT_COLOUR}\">\n"
    ));
    for link in &links {
        draw_link(&mut svg, link, view.size() / ANCHOR_PER_SIDE);
    }
    svg.push_str("</g>\n</g>\n</svg>\n");
    svg
}

/// A body's group, coloured by its type, holding the shapes of its fixtures.
fn draw_body(out: &mut String, bounds: &mut Bounds, scene: &Scene, index: usize, body: &Body) {
    let kind = body.kind();
    let (fill, stroke) = colours(kind);
    let class = kind.map_or_else(|| body.kind.to_string(), |k| lowercase_name(&k));
    let title = format!("{} ({class})", label(scene, "body", index, body.name));
    let _ = writeln!(
        out,
        "<g class=\"{class}\" fill=\"{fill}\" stroke=\"{stroke}\"><title>{}</title>",
        escape(&title)
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
        draw_shape(out, bounds, scene, shape, place, &escape(&title));
    }
    out.push_str("</g>\n");
}

fn draw_shape(
    out: &mut String,
    bounds: &mut Bounds,
    scene: &Scene,
    shape: &Shape,
    place: Placement,
    title: &str,
) {
    let points: Vec<Vec2> = scene.vertices(shape).iter().map(|&v| place.apply(v)).collect();
    let (element, fill) = match shape.kind() {
        Some(ShapeKind::Circle) => return draw_circle(out, bounds, shape, place, title),
        // A two-vertex polygon is a segment; some viewers refuse an SVG polygon of two points.
        Some(ShapeKind::Polygon) if points.len() < 3 => ("polyline", " fill=\"none\""),
        Some(ShapeKind::Polygon) => ("polygon", ""),
        Some(ShapeKind::Chain) if shape.is_loop => ("polygon", " fill=\"none\""),
        Some(ShapeKind::Edge | ShapeKind::Chain) => ("polyline", " fill=\"none\""),
        None => return,
    };
    for &point in &points {
        bounds.include(point);
    }
    let _ = writeln!(
        out,
        "<{element} points=\"{}\"{fill}><title>{title}</title></{element}>",
        point_list(&points)
    );
}

/// A circle, and a radius along the body's local x axis so that its rotation shows.
fn draw_circle(
    out: &mut String,
    bounds: &mut Bounds,
    shape: &Shape,
    place: Placement,
    title: &str,
) {
    let centre = place.apply(shape.position);
    let radius = shape.radius;
    let rim = place.apply(Vec2::new(shape.position.x + radius, shape.position.y));
    bounds.include(Vec2::new(centre.x - radius, centre.y - radius));
    bounds.include(Vec2::new(centre.x + radius, centre.y + radius));
    let _ = writeln!(
        out,
        "<circle cx=\"{}\" cy=\"{}\" r=\"{radius}\"><title>{title}</title></circle>\n\
         <line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
        centre.x, centre.y, centre.x, centre.y, rim.x, rim.y
    );
}

/// What a joint shows: its anchors in the world, joined by a line (through the ground
/// anchors for a pulley).
struct Link {
    title: String,
    points: Vec<Vec2>,
}

/// None when a body it names is not in the scene (a loaded scene never has such a joint).
fn link(scene: &Scene, index: usize, joint: &Joint) -> Option<Link> {
    let body_a = scene.bodies().get(joint.body_a as usize)?;
    let body_b = scene.bodies().get(joint.body_b as usize)?;
    let a = Placement::of(body_a).apply(joint.local_anchor_a);
    let b = Placement::of(body_b).apply(joint.local_anchor_b);
    let kind = joint.kind();
    let points = match kind {
        Some(JointKind::Pulley) => vec![a, joint.ground_anchor_a, joint.ground_anchor_b, b],
        _ => vec![a, b],
    };
    let kind = kind.map_or_else(|| joint.kind.to_string(), |k| lowercase_name(&k));
    let title = format!("{} ({kind})", label(scene, "joint", index, joint.name));
    Some(Link { title, points })
}

fn draw_link(out: &mut String, link: &Link, anchor_radius: f32) {
    let _ = write!(
        out,
        "<g><title>{}</title><polyline points=\"{}\" fill=\"none\"/>",
        escape(&link.title),
        point_list(&link.points)
    );
    let ends = [link.points.first(), link.points.last()];
    for anchor in ends.into_iter().flatten() {
        let _ =
            write!(out, "<circle cx=\"{}\" cy=\"{}\" r=\"{anchor_radius}\"/>", anchor.x, anchor.y);
    }
    out.push_str("</g>\n");
}

/// A body's position and rotation, as Box2D's `b2Transform` holds them.
#[derive(Clone, Copy)]
struct Placement {
    position: Vec2,
    cos: f32,
    sin: f32,
}

impl Placement {
    fn of(body: &Body) -> Placement {
        Placement { position: body.position, cos: body.angle.cos(), sin: body.angle.sin() }
    }

    /// The world point of a point in body coordinates.
    fn apply(self, v: Vec2) -> Vec2 {
        Vec2::new(
            self.cos * v.x - self.sin * v.y + self.position.x,
            self.sin * v.x + self.cos * v.y + self.position.y,
        )
    }
}

/// The smallest box holding every point drawn.
#[derive(Default)]
struct Bounds {
    corners: Option<(Vec2, Vec2)>,
}

impl Bounds {
    fn include(&mut self, p: Vec2) {
        let (lower, upper) = self.corners.get_or_insert((p, p));
        *lower = Vec2::new(lower.x.min(p.x), lower.y.min(p.y));
        *upper = Vec2::new(upper.x.max(p.x), upper.y.max(p.y));
    }
}

/// The view box, in SVG's coordinates (y down): the bounds turned over, with a margin of
/// a twentieth of their larger side (1 m around a single point or an empty scene).
struct View {
    x: f32,
    y: f32,
    width: f32,
    height: f32,
}

impl View {
    fn around(bounds: &Bounds) -> View {
        let (lower, upper) = bounds.corners.unwrap_or_default();
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

    fn size(&self) -> f32 {
        self.width.max(self.height)
    }
}

fn point_list(points: &[Vec2]) -> String {
    let pairs: Vec<String> = points.iter().map(|p| format!("{},{}", p.x, p.y)).collect();
    pairs.join(" ")
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

/// Text for an SVG element: markup escaped, and characters XML does not allow (control
/// characters other than tab and line breaks, U+FFFE, U+FFFF) shown as U+FFFD, so the
/// drawing stays well-formed whatever a name holds.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '\t' | '\n' | '\r' => out.push(c),
            '\u{FFFE}' | '\u{FFFF}' => out.push(char::REPLACEMENT_CHARACTER),
            c if c.is_control() && c < '\u{7F}' => out.push(char::REPLACEMENT_CHARACTER),
            c => out.push(c),
        }
    }
    out
}
