//! How a picture is laid out and written: the view box, the pixels a metre, the title, the
//! key and the labels, and the SVG text of every mark.

use std::fmt::Write;

use super::geometry::{Bounds, Drawing, DrawnBody, Frame, Mark, Point};
use super::labels::{self, LABEL_SIZE, Label};
use crate::escape::svg_text;
use crate::scene::BodyKind;

/// Fill and stroke of a body's shapes by its type (an unknown one as static).
fn colours(kind: Option<BodyKind>) -> (&'static str, &'static str) {
    match kind {
        Some(BodyKind::Static) | None => ("#c8c8c8", "#606060"),
        Some(BodyKind::Kinematic) => ("#b8e0b0", "#3a7a30"),
        Some(BodyKind::Dynamic) => ("#a8c8f0", "#2a5a9a"),
    }
}

const JOINT_COLOUR: &str = "#d03030";
const PATH_COLOUR: &str = "#f08a00";
/// How much of the start shows through when the end is drawn over it.
const START_OPACITY: f32 = 0.3;

/// The world's pixels per metre, unless the picture would be larger than
/// [`LARGEST_WIDTH`] by [`LARGEST_HEIGHT`] or smaller than [`SMALLEST_SIDE`] on its larger
/// side; the title and key widen a narrower picture to [`SMALLEST_SIDE`].
const PIXELS_PER_METRE: f64 = 20.0;
const LARGEST_WIDTH: f64 = 1600.0;
const LARGEST_HEIGHT: f64 = 1000.0;
const SMALLEST_SIDE: f64 = 480.0;

/// Sizes in pixels of the picture.
const LINE: f64 = 1.5;
const PATH_LINE: f64 = 1.25;
const ARM_LINE: f64 = 1.0;
const TITLE_SIZE: f64 = 16.0;
const KEY_SIZE: f64 = 12.0;
const PAD: f64 = 8.0;
/// Around the world.
const MARGIN: f64 = 24.0;
/// The smallest anchor dot; a dot is otherwise a fifth of the smaller body it joins.
const SMALLEST_ANCHOR: f64 = 2.0;

/// The largest coordinate written: viewers compute in single precision, where the view
/// box's corner plus its size, and the points a transform turns over, must stay finite.
const LARGEST: f64 = 1e36;
/// The most pixels a unit written may take: past it (a world of less than half a metre)
/// the numbers are written scaled up, as a huge world's are scaled down, to a unit of one
/// or two pixels. Viewers turn units into pixels in single precision too: a 1e-38 m world
/// drawn in metres would be scaled by 2e40, past it, and show nothing.
const MOST_PIXELS_PER_UNIT: f64 = 1024.0;

impl Drawing {
    pub(super) fn document(&self, title: &str) -> String {
        let mut key = self.key();
        let mut layout = Layout::new(&self.bounds, !title.is_empty(), &key);
        let (labels, hidden) = labels::place(
            &self.labels,
            &self.last().bodies,
            1.0 / layout.pixels_per_metre,
            layout.world,
        );
        if hidden > 0 {
            let names = if hidden == 1 { "name" } else { "names" };
            key.push((Swatch::Hidden, format!("{hidden} {names} only in tooltips")));
            // The key may take another row; the world, and so the labels, stay as they are.
            layout = Layout::new(&self.bounds, !title.is_empty(), &key);
        }
        let w = Writer { scale: layout.scale, pixels_per_metre: layout.pixels_per_metre };
        let mut out = String::new();
        let _ = writeln!(
            out,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
             <svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" width=\"{}\" \
             height=\"{}\" font-family=\"sans-serif\">",
            w.n(layout.x),
            w.n(layout.y),
            w.n(layout.width),
            w.n(layout.height),
            layout.pixel_width as f32,
            layout.pixel_height as f32,
        );
        if !title.is_empty() {
            let _ = writeln!(out, "<title>{}</title>", svg_text(title));
        }
        let _ = writeln!(
            out,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>",
            w.n(layout.x),
            w.n(layout.y),
            w.n(layout.width),
            w.n(layout.height)
        );
        self.write_key(&mut out, &w, &layout, title, &key);

        let _ = writeln!(
            out,
            "<g class=\"world\" transform=\"scale(1,-1)\" stroke-width=\"{}\" \
             stroke-linejoin=\"round\" stroke-linecap=\"round\">",
            w.n(w.px(LINE))
        );
        match &self.end {
            Some(end) => {
                let _ = writeln!(out, "<g class=\"start\" opacity=\"{START_OPACITY}\">");
                w.frame(&mut out, &self.start);
                out.push_str("</g>\n");
                w.paths(&mut out, &self.paths);
                out.push_str("<g class=\"end\">\n");
                w.frame(&mut out, end);
                out.push_str("</g>\n");
            }
            None => {
                w.paths(&mut out, &self.paths);
                out.push_str("<g class=\"start\">\n");
                w.frame(&mut out, &self.start);
                out.push_str("</g>\n");
            }
        }
        out.push_str("</g>\n");
        w.labels(&mut out, &labels);
        out.push_str("</svg>\n");
        out
    }

    /// The key's entries: a swatch and its words, for what the picture holds.
    fn key(&self) -> Vec<(Swatch, String)> {
        let mut key = Vec::new();
        // A body of a kind with no name is coloured, and keyed, as a static one.
        let drawn = |kind| {
            let mut bodies = self.start.bodies.iter().flatten();
            bodies.any(|b| b.kind.unwrap_or(BodyKind::Static) == kind)
        };
        for kind in [BodyKind::Static, BodyKind::Kinematic, BodyKind::Dynamic] {
            if drawn(kind) {
                key.push((Swatch::Body(Some(kind), 1.0), kind.name().to_owned()));
            }
        }
        if self.start.joints.iter().chain(self.end.iter().flat_map(|f| &f.joints)).next().is_some()
        {
            key.push((Swatch::Joint, "joint".to_owned()));
        }
        if self.end.is_some() {
            key.push((
                Swatch::Body(Some(BodyKind::Dynamic), START_OPACITY),
                "start (faint)".into(),
            ));
            key.push((Swatch::Body(Some(BodyKind::Dynamic), 1.0), "end (solid)".into()));
        }
        if !self.paths.is_empty() {
            key.push((Swatch::Path, "path of a body's origin".to_owned()));
        }
        key
    }

    fn write_key(
        &self,
        out: &mut String,
        w: &Writer,
        layout: &Layout,
        title: &str,
        key: &[(Swatch, String)],
    ) {
        out.push_str("<g class=\"key\">\n");
        let left = layout.x + w.px(PAD);
        if !title.is_empty() {
            let _ = writeln!(
                out,
                "<text x=\"{}\" y=\"{}\" font-size=\"{}\" font-weight=\"bold\">{}</text>",
                w.n(left),
                w.n(layout.y + w.px(PAD + TITLE_SIZE)),
                w.n(w.px(TITLE_SIZE)),
                svg_text(title)
            );
        }
        for (entry, &(row, column)) in key.iter().zip(&layout.key_places) {
            let x = left + w.px(column);
            let middle = layout.y + w.px(layout.key_top + row * KEY_ROW + KEY_SIZE / 2.0);
            let (swatch, words) = entry;
            w.swatch(out, *swatch, x, middle);
            let _ = writeln!(
                out,
                "<text x=\"{}\" y=\"{}\" font-size=\"{}\" dominant-baseline=\"central\">{}</text>",
                w.n(x + w.px(SWATCH + SWATCH_GAP)),
                w.n(middle),
                w.n(w.px(KEY_SIZE)),
                words
            );
        }
        out.push_str("</g>\n");
    }
}

/// What a key entry shows beside its words.
#[derive(Clone, Copy)]
enum Swatch {
    /// A square in a body type's colours, at an opacity.
    Body(Option<BodyKind>, f32),
    Joint,
    Path,
    /// Names left to the tooltips: an ellipsis in the labels' style.
    Hidden,
}

/// A key entry's swatch, the gap after it, a row's height, the gap between entries.
const SWATCH: f64 = 12.0;
const SWATCH_GAP: f64 = 5.0;
const KEY_ROW: f64 = 20.0;
const ENTRY_GAP: f64 = 18.0;
/// The width of a character of the key, estimated (a viewer's sans-serif at 12 px).
const KEY_CHAR: f64 = 7.0;

/// Where the world and the header go, in metres of the world, and the picture's pixels.
struct Layout {
    /// The view box, in SVG's coordinates (y down), before scaling.
    x: f64,
    y: f64,
    width: f64,
    height: f64,
    pixel_width: f64,
    pixel_height: f64,
    pixels_per_metre: f64,
    /// What the picture shows of the world (not the header), in metres, y up.
    world: (Point, Point),
    /// The key's first row, in pixels from the top.
    key_top: f64,
    /// Each key entry's row and its left edge in pixels from the left padding.
    key_places: Vec<(f64, f64)>,
    /// What every number is multiplied by as it is written: 1, or a power of two (less
    /// for a huge world, more for a tiny one).
    scale: f64,
}

impl Layout {
    fn new(bounds: &Bounds, titled: bool, key: &[(Swatch, String)]) -> Layout {
        // The world; 1 m around a single point or an empty scene.
        let origin = Point { x: 0.0, y: 0.0 };
        let (mut lower, mut upper) = bounds.corners.unwrap_or((origin, origin));
        if upper.x - lower.x <= 0.0 && upper.y - lower.y <= 0.0 {
            (lower, upper) = (
                Point { x: lower.x - 1.0, y: lower.y - 1.0 },
                Point { x: upper.x + 1.0, y: upper.y + 1.0 },
            );
        }
        let (width, height) = (upper.x - lower.x, upper.y - lower.y);
        let room = |side: f64, pixels: f64| (pixels - 2.0 * MARGIN) / side;
        let mut pixels_per_metre = PIXELS_PER_METRE
            .min(room(width, LARGEST_WIDTH))
            .min(room(height, LARGEST_HEIGHT))
            .max(room(width.max(height), SMALLEST_SIDE));
        if !(pixels_per_metre.is_finite() && pixels_per_metre > 0.0) {
            pixels_per_metre = 1.0;
        }
        let margin = MARGIN / pixels_per_metre;
        let (mut width, height) = (width + 2.0 * margin, height + 2.0 * margin);
        let mut x = lower.x - margin;
        // A narrow world is centred in a picture as wide as the header needs.
        let header_width = SMALLEST_SIDE / pixels_per_metre;
        if width < header_width {
            x -= (header_width - width) / 2.0;
            width = header_width;
        }
        let pixel_width = width * pixels_per_metre;

        let key_top = PAD + if titled { TITLE_SIZE + PAD } else { 0.0 };
        let mut key_places = Vec::new();
        let (mut row, mut column) = (0.0, 0.0);
        for (_, words) in key {
            let entry = SWATCH + SWATCH_GAP + words.len() as f64 * KEY_CHAR;
            if column > 0.0 && column + entry > pixel_width - 2.0 * PAD {
                (row, column) = (row + 1.0, 0.0);
            }
            key_places.push((row, column));
            column += entry + ENTRY_GAP;
        }
        let rows = if key.is_empty() { 0.0 } else { row + 1.0 };
        let header = key_top + rows * KEY_ROW + if titled || rows > 0.0 { PAD } else { 0.0 };
        let header_metres = header / pixels_per_metre;
        let world = (Point { x, y: lower.y - margin }, Point { x: x + width, y: upper.y + margin });
        let y = -(upper.y + margin) - header_metres;
        let height = height + header_metres;

        let corners = [x, y, x + width, y + height];
        let extent = corners.into_iter().fold(0.0, |most: f64, v| most.max(v.abs()));
        let scale = match (extent <= LARGEST, pixels_per_metre <= MOST_PIXELS_PER_UNIT) {
            (true, true) => 1.0,
            (false, _) => 2f64.powi(-((extent / LARGEST).log2().ceil() as i32)),
            // No further than the largest coordinate allows, for a tiny world far out.
            (true, false) => 2f64.powi(
                (pixels_per_metre.log2().floor()).min((LARGEST / extent).log2().floor()) as i32,
            ),
        };
        Layout {
            x,
            y,
            width,
            height,
            pixel_width,
            pixel_height: height * pixels_per_metre,
            pixels_per_metre,
            world,
            key_top,
            key_places,
            scale,
        }
    }
}

/// Writes coordinates and lengths in metres times the layout's scale.
struct Writer {
    scale: f64,
    pixels_per_metre: f64,
}

impl Writer {
    /// A size in pixels of the picture, in metres of the world.
    fn px(&self, pixels: f64) -> f64 {
        pixels / self.pixels_per_metre
    }

    /// A coordinate or a length as written; a negative zero (a y of 0 turned over) as 0.
    fn n(&self, v: f64) -> f32 {
        (v * self.scale) as f32 + 0.0
    }

    /// A y of the world as written outside the turned-over group.
    fn flipped(&self, y: f64) -> f32 {
        self.n(-y)
    }

    fn points(&self, points: &[Point]) -> String {
        let pairs: Vec<String> =
            points.iter().map(|p| format!("{},{}", self.n(p.x), self.n(p.y))).collect();
        pairs.join(" ")
    }

    /// Segments as the `d` of an SVG path.
    fn path(&self, segments: &[[Point; 2]]) -> String {
        let moves: Vec<String> = segments.iter().map(|s| format!("M{}", self.points(s))).collect();
        moves.join(" ")
    }

    fn frame(&self, out: &mut String, frame: &Frame) {
        for body in frame.bodies.iter().flatten() {
            self.body(out, body);
        }
        if frame.joints.is_empty() {
            return;
        }
        let _ =
            writeln!(out, "<g class=\"joints\" fill=\"{JOINT_COLOUR}\" stroke=\"{JOINT_COLOUR}\">");
        for joint in &frame.joints {
            let _ = write!(
                out,
                "<g><title>{}</title><path d=\"{}\" fill=\"none\"/>",
                svg_text(&joint.title),
                self.path(&joint.segments)
            );
            if !joint.arms.is_empty() {
                let _ = write!(
                    out,
                    "<path class=\"arms\" d=\"{}\" fill=\"none\" stroke-opacity=\"0.45\" \
                     stroke-width=\"{}\"/>",
                    self.path(&joint.arms),
                    self.n(self.px(ARM_LINE))
                );
            }
            let radius = self.n(joint.anchor_radius.unwrap_or(0.0).max(self.px(SMALLEST_ANCHOR)));
            for anchor in joint.anchors {
                let (x, y) = (self.n(anchor.x), self.n(anchor.y));
                let _ =
                    write!(out, "<circle cx=\"{x}\" cy=\"{y}\" r=\"{radius}\" stroke=\"none\"/>");
            }
            out.push_str("</g>\n");
        }
        out.push_str("</g>\n");
    }

    fn body(&self, out: &mut String, body: &DrawnBody) {
        let (fill, stroke) = colours(body.kind);
        let _ = writeln!(
            out,
            "<g class=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\"><title>{}</title>",
            svg_text(&body.class),
            svg_text(&body.title)
        );
        for (mark, title) in &body.marks {
            let title = svg_text(title);
            match mark {
                Mark::Polygon(points) => self.shape(out, "polygon", "", points, &title),
                Mark::Polyline(points) => {
                    self.shape(out, "polyline", " fill=\"none\"", points, &title)
                }
                Mark::Loop(points) => self.shape(out, "polygon", " fill=\"none\"", points, &title),
                Mark::Circle { centre, radius, rim } => {
                    let _ = writeln!(
                        out,
                        "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"><title>{title}</title></circle>\n\
                         <line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
                        self.n(centre.x),
                        self.n(centre.y),
                        self.n(*radius),
                        self.n(centre.x),
                        self.n(centre.y),
                        self.n(rim.x),
                        self.n(rim.y)
                    );
                }
            }
        }
        out.push_str("</g>\n");
    }

    fn shape(&self, out: &mut String, element: &str, fill: &str, points: &[Point], title: &str) {
        let points = self.points(points);
        let _ = writeln!(
            out,
            "<{element} points=\"{points}\"{fill}><title>{title}</title></{element}>"
        );
    }

    fn paths(&self, out: &mut String, paths: &[Vec<Point>]) {
        if paths.is_empty() {
            return;
        }
        let _ = writeln!(
            out,
            "<g class=\"paths\" fill=\"none\" stroke=\"{PATH_COLOUR}\" stroke-width=\"{}\">",
            self.n(self.px(PATH_LINE))
        );
        for path in paths {
            let _ = writeln!(out, "<polyline points=\"{}\"/>", self.points(path));
        }
        out.push_str("</g>\n");
    }

    /// Each name where [`labels::place`] put it, on a white halo.
    fn labels(&self, out: &mut String, labels: &[Label<'_>]) {
        let mut texts = String::new();
        for Label { name, at } in labels {
            let _ = writeln!(
                texts,
                "<text x=\"{}\" y=\"{}\">{}</text>",
                self.n(at.x),
                self.flipped(at.y),
                svg_text(name)
            );
        }
        if texts.is_empty() {
            return;
        }
        let _ = writeln!(
            out,
            "<g class=\"labels\" font-size=\"{}\" text-anchor=\"middle\" fill=\"#202020\" \
             stroke=\"white\" stroke-width=\"{}\" paint-order=\"stroke\">",
            self.n(self.px(LABEL_SIZE)),
            self.n(self.px(3.0))
        );
        out.push_str(&texts);
        out.push_str("</g>\n");
    }

    fn swatch(&self, out: &mut String, swatch: Swatch, x: f64, middle: f64) {
        let (left, right, top) =
            (self.n(x), self.n(x + self.px(SWATCH)), self.n(middle - self.px(SWATCH / 2.0)));
        let y = self.n(middle);
        match swatch {
            Swatch::Body(kind, opacity) => {
                let (fill, stroke) = colours(kind);
                let side = self.n(self.px(SWATCH));
                let _ = writeln!(
                    out,
                    "<rect x=\"{left}\" y=\"{top}\" width=\"{side}\" height=\"{side}\" \
                     fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{}\" opacity=\"{opacity}\"/>",
                    self.n(self.px(LINE))
                );
            }
            Swatch::Joint => {
                let _ = writeln!(
                    out,
                    "<line x1=\"{left}\" y1=\"{y}\" x2=\"{right}\" y2=\"{y}\" stroke=\"{JOINT_COLOUR}\" \
                     stroke-width=\"{}\"/><circle cx=\"{left}\" cy=\"{y}\" r=\"{}\" \
                     fill=\"{JOINT_COLOUR}\"/><circle cx=\"{right}\" cy=\"{y}\" r=\"{}\" \
                     fill=\"{JOINT_COLOUR}\"/>",
                    self.n(self.px(LINE)),
                    self.n(self.px(2.5)),
                    self.n(self.px(2.5))
                );
            }
            Swatch::Hidden => {
                let _ = writeln!(
                    out,
                    "<text x=\"{}\" y=\"{y}\" font-size=\"{}\" text-anchor=\"middle\" \
                     dominant-baseline=\"central\" fill=\"#202020\">\u{2026}</text>",
                    self.n(x + self.px(SWATCH / 2.0)),
                    self.n(self.px(LABEL_SIZE))
                );
            }
            Swatch::Path => {
                let _ = writeln!(
                    out,
                    "<line x1=\"{left}\" y1=\"{y}\" x2=\"{right}\" y2=\"{y}\" stroke=\"{PATH_COLOUR}\" \
                     stroke-width=\"{}\"/>",
                    self.n(self.px(PATH_LINE))
                );
            }
        }
    }
}
