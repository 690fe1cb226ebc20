//! Where each named body's name goes: beside one of its own shapes, clear of every shape
//! drawn and of the names placed before it, inside the picture. A name is never put at
//! the middle of a body's bounds, which for a large body (the ground around a level) may
//! be far from anything of its own and next to another body; a name with no free place is
//! left to its body's tooltip, and the key counts those.

use super::geometry::{Bounds, DrawnBody, Mark, Point};

/// A label's font size, the width of one of its characters (estimated: a viewer's
/// sans-serif), and its distance from its shape, in pixels.
pub(super) const LABEL_SIZE: f64 = 11.0;
const LABEL_CHAR: f64 = 7.0;
const GAP: f64 = 3.0;

/// How much of a label's box is under its baseline, in font sizes.
const DESCENT: f64 = 0.25;

/// A box, lower and upper corners, y up.
type Rect = (Point, Point);

/// A name placed: the middle of its baseline, in metres.
pub(super) struct Label<'a> {
    pub(super) name: &'a str,
    pub(super) at: Point,
}

/// Each of `names` (a name and the index of its body in `bodies`), in order, at the first
/// free place beside its body's shapes, the larger shapes first; and how many found none.
/// `metre` is a pixel's size in metres, `view` what the picture shows of the world.
pub(super) fn place<'a>(
    names: &'a [(String, usize)],
    bodies: &[Option<DrawnBody>],
    metre: f64,
    view: Rect,
) -> (Vec<Label<'a>>, usize) {
    let mut taken = Taken::new(view, bodies);
    // A label keeps as far from another body's shapes as from its own, so that it is never
    // nearer another body than the one it names.
    let clearance = GAP * metre;
    let mut labels = Vec::new();
    for (name, index) in names {
        let Some(Some(body)) = bodies.get(*index) else { continue };
        let width = name.chars().count() as f64 * LABEL_CHAR * metre;
        let mut shapes: Vec<Rect> =
            body.marks.iter().filter_map(|(m, _)| m.bounds().corners).collect();
        shapes.sort_by(|a, b| side(*b).total_cmp(&side(*a)));
        let free = shapes
            .iter()
            .flat_map(|&shape| places(shape, width, metre))
            .find(|&(_, rect)| inside(rect, view) && !taken.hits(rect, *index, clearance));
        if let Some((at, rect)) = free {
            taken.label(rect);
            labels.push(Label { name, at });
        }
    }
    let hidden = names.len() - labels.len();
    (labels, hidden)
}

/// The larger side of a box.
fn side((lower, upper): Rect) -> f64 {
    (upper.x - lower.x).max(upper.y - lower.y)
}

/// The places beside `shape` for a label `width` wide, each the middle of its baseline and
/// its box, in the order tried: centred above and below, to the right and to the left,
/// at the four corners, then, along a shape several labels wide, above and below its
/// quarters.
fn places((lower, upper): Rect, width: f64, metre: f64) -> Vec<(Point, Rect)> {
    let (gap, size) = (GAP * metre, LABEL_SIZE * metre);
    let above = upper.y + gap;
    let below = lower.y - gap - size;
    let middle = (lower.y + upper.y) / 2.0 - (1.0 - DESCENT) / 2.0 * size;
    let centre = (lower.x + upper.x) / 2.0;
    let mut at = vec![
        Point { x: centre, y: above },
        Point { x: centre, y: below },
        Point { x: upper.x + gap + width / 2.0, y: middle },
        Point { x: lower.x - gap - width / 2.0, y: middle },
        Point { x: upper.x + width / 2.0, y: above },
        Point { x: lower.x - width / 2.0, y: above },
        Point { x: upper.x + width / 2.0, y: below },
        Point { x: lower.x - width / 2.0, y: below },
    ];
    if upper.x - lower.x > 4.0 * width {
        let quarter = (upper.x - lower.x) / 4.0;
        for y in [above, below] {
            at.push(Point { x: lower.x + quarter, y });
            at.push(Point { x: upper.x - quarter, y });
        }
    }
    let rect = |p: Point| {
        let lower = Point { x: p.x - width / 2.0, y: p.y - DESCENT * size };
        (lower, Point { x: p.x + width / 2.0, y: p.y + size })
    };
    at.into_iter().map(|p| (p, rect(p))).collect()
}

/// Whether `a` lies within `b`.
fn inside(a: Rect, b: Rect) -> bool {
    b.0.x <= a.0.x && a.1.x <= b.1.x && b.0.y <= a.0.y && a.1.y <= b.1.y
}

/// Whether two boxes share more than an edge.
fn overlap(a: Rect, b: Rect) -> bool {
    a.0.x < b.1.x && b.0.x < a.1.x && a.0.y < b.1.y && b.0.y < a.1.y
}

/// What a label must not cover: every piece of every shape drawn and every label placed,
/// found through a grid over the view, so that a picture of many bodies, or a chain of
/// many vertices, costs a few tests a place.
struct Taken<'a> {
    /// Each piece, with the index of its shape's body (None for a label).
    pieces: Vec<(Piece<'a>, Option<usize>)>,
    /// Per cell, row after row: the pieces whose box reaches into it.
    cells: Vec<Vec<usize>>,
    origin: Point,
    cell: Point,
}

/// A piece of what is drawn.
#[derive(Clone, Copy)]
enum Piece<'a> {
    /// A side of a polygon or a loop, or a link of a chain.
    Segment(Point, Point),
    /// A circle, filled.
    Disc(Point, f64),
    /// The inside of a polygon (at most eight vertices).
    Inside(&'a [Point]),
    Label(Rect),
}

/// Cells a side of the grid.
const CELLS: usize = 64;

impl<'a> Taken<'a> {
    fn new((lower, upper): Rect, bodies: &'a [Option<DrawnBody>]) -> Taken<'a> {
        let mut taken = Taken {
            pieces: Vec::new(),
            cells: vec![Vec::new(); CELLS * CELLS],
            origin: lower,
            cell: Point {
                x: (upper.x - lower.x) / CELLS as f64,
                y: (upper.y - lower.y) / CELLS as f64,
            },
        };
        for (index, body) in bodies.iter().enumerate() {
            for (mark, _) in body.iter().flat_map(|body| &body.marks) {
                let body = Some(index);
                match mark {
                    Mark::Circle { centre, radius, .. } => {
                        taken.add(Piece::Disc(*centre, *radius), body)
                    }
                    Mark::Polyline(points) => {
                        for link in points.windows(2) {
                            taken.add(Piece::Segment(link[0], link[1]), body);
                        }
                    }
                    Mark::Loop(points) | Mark::Polygon(points) => {
                        for (a, b) in outline(points) {
                            taken.add(Piece::Segment(a, b), body);
                        }
                    }
                }
                if let Mark::Polygon(points) = mark {
                    taken.add(Piece::Inside(points), body);
                }
            }
        }
        taken
    }

    /// Takes `rect` for a label.
    fn label(&mut self, rect: Rect) {
        self.add(Piece::Label(rect), None);
    }

    fn add(&mut self, piece: Piece<'a>, body: Option<usize>) {
        let mut bounds = Bounds::default();
        match piece {
            Piece::Segment(a, b) => [a, b].into_iter().for_each(|p| bounds.include(p)),
            Piece::Disc(centre, radius) => bounds.include_circle(centre, radius),
            Piece::Inside(points) => points.iter().for_each(|&p| bounds.include(p)),
            Piece::Label((lower, upper)) => {
                [lower, upper].into_iter().for_each(|p| bounds.include(p))
            }
        }
        let Some(rect) = bounds.corners else { return };
        let cells: Vec<usize> = self.cells_of(rect).collect();
        for cell in cells {
            self.cells[cell].push(self.pieces.len());
        }
        self.pieces.push((piece, body));
    }

    /// The cells `rect` reaches into.
    fn cells_of(&self, (lower, upper): Rect) -> impl Iterator<Item = usize> + use<> {
        let index = |v: f64, origin: f64, cell: f64| {
            let i = ((v - origin) / cell).floor();
            if i.is_nan() { 0 } else { i.clamp(0.0, (CELLS - 1) as f64) as usize }
        };
        let columns =
            index(lower.x, self.origin.x, self.cell.x)..=index(upper.x, self.origin.x, self.cell.x);
        let rows =
            index(lower.y, self.origin.y, self.cell.y)..=index(upper.y, self.origin.y, self.cell.y);
        rows.flat_map(move |row| columns.clone().map(move |column| row * CELLS + column))
    }

    /// Whether a label of body `own` at `rect` would cover a label or a shape, or come
    /// within `clearance` of another body's shape.
    fn hits(&self, rect: Rect, own: usize, clearance: f64) -> bool {
        let wide = (
            Point { x: rect.0.x - clearance, y: rect.0.y - clearance },
            Point { x: rect.1.x + clearance, y: rect.1.y + clearance },
        );
        self.cells_of(wide).flat_map(|cell| &self.cells[cell]).any(|&piece| {
            let (piece, body) = self.pieces[piece];
            covers(if body == Some(own) || body.is_none() { rect } else { wide }, piece)
        })
    }
}

/// Whether `rect` covers part of `piece`.
fn covers(rect: Rect, piece: Piece<'_>) -> bool {
    match piece {
        Piece::Segment(a, b) => crosses(rect, a, b),
        Piece::Disc(c, radius) => {
            let dx = c.x - c.x.clamp(rect.0.x, rect.1.x);
            let dy = c.y - c.y.clamp(rect.0.y, rect.1.y);
            dx * dx + dy * dy <= radius * radius
        }
        // A polygon's sides are pieces of their own: here, whether the box is inside it.
        Piece::Inside(points) => {
            let centre = Point { x: (rect.0.x + rect.1.x) / 2.0, y: (rect.0.y + rect.1.y) / 2.0 };
            encloses(points, centre)
        }
        Piece::Label(label) => overlap(rect, label),
    }
}

/// The sides of a closed outline.
fn outline(points: &[Point]) -> impl Iterator<Item = (Point, Point)> + '_ {
    points.iter().zip(points.iter().cycle().skip(1)).map(|(&a, &b)| (a, b))
}

/// Whether the segment from `a` to `b` passes through `rect` (Liang and Barsky's clip).
fn crosses(rect: Rect, a: Point, b: Point) -> bool {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let (mut enter, mut leave) = (0.0f64, 1.0f64);
    let sides =
        [(-dx, a.x - rect.0.x), (dx, rect.1.x - a.x), (-dy, a.y - rect.0.y), (dy, rect.1.y - a.y)];
    for (p, q) in sides {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                enter = enter.max(t);
            } else {
                leave = leave.min(t);
            }
        }
    }
    enter <= leave
}

/// Whether `p` is inside the polygon (even-odd rule).
fn encloses(points: &[Point], p: Point) -> bool {
    let mut inside = false;
    for (a, b) in outline(points) {
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            inside = !inside;
        }
    }
    inside
}
