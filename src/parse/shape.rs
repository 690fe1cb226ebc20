//! `<Shape Type="...">`: circles, polygons, and the Version 2 edges and chains.

use super::{Element, Reader, Seen, Tag, attributes, elements};
use crate::error::{Code, Parsed, problem};
use crate::markup::Name;
use crate::rules;
use crate::scene::{Object, PoolStr, Range, Shape, ShapeKind, Vec2};

elements! {
    enum ShapeChild {
        Name,
        Radius,
        Position,
        Vertices,
        Centroid,
        Vertex0,
        Vertex1,
        Vertex2,
        Vertex3,
        HasVertex0,
        HasVertex3,
        PrevVertex,
        NextVertex,
        HasPrevVertex,
        HasNextVertex,
        Loop,
    }
}

/// Whether a shape of `kind` has the element `name`.
fn belongs(kind: ShapeKind, name: ShapeChild) -> bool {
    use ShapeChild::*;
    match name {
        Name => true,
        Radius | Position => kind == ShapeKind::Circle,
        Vertices => matches!(kind, ShapeKind::Polygon | ShapeKind::Chain),
        Centroid => kind == ShapeKind::Polygon,
        Vertex0 | Vertex1 | Vertex2 | Vertex3 | HasVertex0 | HasVertex3 => kind == ShapeKind::Edge,
        PrevVertex | NextVertex | HasPrevVertex | HasNextVertex | Loop => kind == ShapeKind::Chain,
    }
}

impl<'a> Reader<'a> {
    pub(super) fn shape(&mut self, tag: &Tag) -> Parsed<()> {
        self.begin_object(Object::Shape(self.arena.scene.shapes.len() as u32));
        let (mut shape, mut name_str) = self.shape_type(tag)?;
        let kind = shape.kind().expect("shape_type sets a known kind");
        let mut seen = Seen::default();
        let (mut radius_at, mut edge) = (tag.at, [Vec2::ZERO; 2]);
        let mut child = Tag::slot();
        while self.tok.child(tag, &mut child)? {
            let Some((name, repeated)) = self.known(tag, &child, &mut seen)? else {
                continue;
            };
            if !belongs(kind, name) {
                let words =
                    || format!("<{}> does not belong in a {kind:?} shape; ignored", child.name());
                self.ignore(&child, words)?;
                continue;
            }
            if repeated && name == ShapeChild::Vertices {
                return Err(self.tok.duplicate_container(tag, &child));
            }
            if repeated {
                self.duplicate(tag, &child)?;
            }
            use ShapeChild::*;
            match name {
                Name => {
                    if !repeated && name_str.is_some() {
                        let message = "<Shape> has both a Name attribute and a <Name> element; \
                                       the element wins";
                        self.warn(Code::DuplicateElement, child.at, || message)?;
                    }
                    name_str = Some(self.string(&child)?);
                }
                Radius => (shape.radius, radius_at) = self.value(&child, crate::text::float)?,
                Position => shape.position = self.vector(&child)?,
                Vertices => shape.vertices = self.vertices(&child, kind)?,
                Centroid => {
                    shape.centroid = self.vector(&child)?;
                    shape.centroid_given = true;
                }
                Vertex0 | PrevVertex => shape.prev_vertex = self.vector(&child)?,
                Vertex1 => edge[0] = self.vector(&child)?,
                Vertex2 => edge[1] = self.vector(&child)?,
                Vertex3 | NextVertex => shape.next_vertex = self.vector(&child)?,
                HasVertex0 | HasPrevVertex => shape.has_prev_vertex = self.boolean(&child)?,
                HasVertex3 | HasNextVertex => shape.has_next_vertex = self.boolean(&child)?,
                Loop => shape.is_loop |= self.boolean(&child)?,
            }
        }
        match kind {
            ShapeKind::Circle => {
                for needed in [ShapeChild::Radius, ShapeChild::Position] {
                    if !seen.contains(needed) {
                        return Err(self
                            .tok
                            .missing(tag, &format!("<{}> (a Circle needs one)", needed.name())));
                    }
                }
                self.recovered(rules::circle(shape.radius, radius_at), ())?;
            }
            ShapeKind::Edge => {
                for needed in [ShapeChild::Vertex1, ShapeChild::Vertex2] {
                    if !seen.contains(needed) {
                        return Err(self
                            .tok
                            .missing(tag, &format!("<{}> (an Edge needs one)", needed.name())));
                    }
                }
                let first = self.arena.scene.vertices.len() as u32;
                self.arena.scene.vertices.extend(edge);
                shape.vertices = Range { first, count: 2 };
            }
            ShapeKind::Polygon | ShapeKind::Chain => {
                if !seen.contains(ShapeChild::Vertices) {
                    return Err(self.tok.missing(tag, "<Vertices>"));
                }
            }
        }
        let flags = [ShapeChild::HasPrevVertex, ShapeChild::HasNextVertex, ShapeChild::Loop]
            .map(|flag| seen.contains(flag));
        if kind == ShapeKind::Chain && !shape.is_loop && flags == [false; 3] {
            let index = self.arena.scene.shapes.len() as u32;
            self.arena.origins.flagless_chains.push(index);
        }
        self.check_geometry(tag, &shape)?;
        self.end_object();
        self.arena.scene.push_shape(shape, name_str);
        Ok(())
    }

    /// The shape's `Type` (and `Name` attribute, which some writers use; and in Version 3,
    /// the `Density` of the fixtures made with it).
    fn shape_type(&mut self, tag: &Tag) -> Parsed<(Shape, Option<PoolStr>)> {
        let known: &[&str] = if self.arena.farseer_layout() {
            &["Type", "Name", "Density"]
        } else {
            &["Type", "Name"]
        };
        let attrs = attributes!(self, tag, known);
        let density =
            attrs.iter().find(|a| a.is("density")).filter(|_| self.arena.farseer_layout());
        let density = density.map(|attr| {
            (self.tok.attribute(tag, attr, crate::text::float))
                .and_then(|(d, at)| rules::not_negative("the shape's Density", d, at))
        });
        // What the rest needs of the attributes, taken before the reader goes on, as the
        // attributes borrow its text: the Type as written, copied in place (a known one is
        // short), and the name, pooled.
        let ty = attrs.iter().find(|a| a.is("type"));
        let ty = ty.map(|ty| (ty.at, Name::new(super::trim_xml(&ty.value))));
        let name = attrs.iter().find(|a| a.is("name"));
        let name = name.map(|name| self.arena.scene.add_str(super::trim_xml(&name.value)));
        let density = match density {
            Some(checked) => self.recovered(checked, 0.0)?,
            None => 0.0,
        };
        self.arena.origins.shape_densities.push(density);
        let Some((at, value)) = ty else {
            return Err(problem(
                Code::MissingAttribute,
                tag.at,
                "<Shape> has no Type attribute (Circle, Polygon, Edge or Chain)",
            ));
        };
        let value = value.as_str();
        let (kind, is_loop) = match super::lowercase(value, &mut [0; 16]) {
            b"circle" => (ShapeKind::Circle, false),
            b"polygon" => (ShapeKind::Polygon, false),
            b"edge" => (ShapeKind::Edge, false),
            b"chain" => (ShapeKind::Chain, false),
            b"loop" => (ShapeKind::Chain, true),
            _ => {
                return Err(problem(
                    Code::UnknownType,
                    at,
                    format!(
                        "unknown shape Type \"{}\"{}: expected Circle, Polygon, Edge or Chain",
                        super::shorten(value),
                        super::did_you_mean(value, &["Circle", "Polygon", "Edge", "Chain", "Loop"])
                    ),
                ));
            }
        };
        if matches!(kind, ShapeKind::Edge | ShapeKind::Chain) {
            self.newer_construct(at, format_args!("a {value} shape"))?;
        }
        let mut shape = Shape::new(kind);
        shape.is_loop = is_loop;
        Ok((shape, name))
    }

    /// `<Vertices>` of a polygon (at most 8) or a chain (at most the chain limit).
    fn vertices(&mut self, tag: &Tag, kind: ShapeKind) -> Parsed<Range> {
        let first = self.arena.scene.vertices.len();
        let most = match kind {
            ShapeKind::Polygon => rules::MAX_POLYGON_VERTICES,
            _ => self.tok.options().max_chain_vertices as usize,
        };
        self.items(tag, "Vertex", |p, vertex| {
            if p.arena.scene.vertices.len() - first == most {
                return Err(match kind {
                    ShapeKind::Polygon => problem(
                        Code::BadVertexCount,
                        vertex.at,
                        format!("a polygon has at most {most} vertices (Box2D's b2_maxPolygonVertices); this is the {}th", most + 1),
                    ),
                    _ => p.tok.limit(vertex.at, "max_chain_vertices", most as u64),
                });
            }
            let v = p.vector(vertex)?;
            p.arena.scene.vertices.push(v);
            Ok(())
        })?;
        Ok(Range::between(first, self.arena.scene.vertices.len()))
    }

    fn check_geometry(&mut self, tag: &Tag, shape: &Shape) -> Parsed<()> {
        let vertices = &self.arena.scene.vertices[shape.vertices.indices()];
        let checked = match shape.kind() {
            Some(ShapeKind::Polygon) => rules::polygon(vertices, tag.at),
            Some(ShapeKind::Edge) => rules::edge(vertices, tag.at),
            Some(ShapeKind::Chain) => rules::chain(vertices, shape.is_loop, tag.at),
            _ => Ok(None),
        };
        let warning = self.recovered(checked, None)?;
        match warning {
            Some(warning) => self.note(warning),
            None => Ok(()),
        }
    }
}
