//! `<Body Type="...">`: state, flags, mass override and fixture IDs.

use super::{Names, Parsed, Parser, Seen, Tag, problem};
use crate::error::Code;
use crate::scene::{Body, BodyKind, MassData, Range};

const BODY: &Names = &Names::new(&[
    "name",
    "active",
    "allowsleep",
    "awake",
    "bullet",
    "fixedrotation",
    "angle",
    "angulardamping",
    "angularvelocity",
    "lineardamping",
    "linearvelocity",
    "position",
    "inertiascale",
    "gravityscale",
    "massdata",
    "fixtures",
    "userdata",
    "bindings",
]);
const MASS_DATA: &Names = &Names::new(&["mass", "center", "inertia"]);

impl<'a> Parser<'a> {
    pub(super) fn body(&mut self, tag: Tag) -> Parsed<()> {
        let mut body = Body::new(self.body_type(&tag)?);
        let mut seen = Seen::default();
        while let Some(child) = self.child(&tag)? {
            let Some((name, repeated)) = self.known(&tag, &child, BODY, &mut seen)? else {
                continue;
            };
            if repeated && matches!(name, "fixtures" | "bindings") {
                return Err(self.duplicate_container(&tag, &child));
            }
            if let Some(problem) = self.layout_mismatch(&child, name) {
                return Err(problem);
            }
            if repeated {
                self.duplicate(&tag, &child)?;
            }
            match name {
                "name" => body.name = self.string(&child)?,
                "active" => body.active = self.boolean(&child)?,
                "allowsleep" => body.allow_sleep = self.boolean(&child)?,
                "awake" => body.awake = self.boolean(&child)?,
                "bullet" => body.bullet = self.boolean(&child)?,
                "fixedrotation" => body.fixed_rotation = self.boolean(&child)?,
                "angle" => body.angle = self.float(&child)?,
                // Negative damping is not an error of the format; the Box2D adapter, whose
                // engine asserts against it, reports it and uses 0.
                "angulardamping" => body.angular_damping = self.float(&child)?,
                "angularvelocity" => body.angular_velocity = self.float(&child)?,
                "lineardamping" => body.linear_damping = self.float(&child)?,
                "linearvelocity" => body.linear_velocity = self.vector(&child)?,
                "position" => body.position = self.vector(&child)?,
                "inertiascale" => body.inertia_scale = self.float(&child)?,
                "gravityscale" => {
                    self.newer_construct(child.at, "<GravityScale>")?;
                    body.gravity_scale = self.float(&child)?;
                }
                "massdata" => self.mass_data(&child, &mut body.mass_data)?,
                "fixtures" => body.fixtures = self.fixture_ids(&child)?,
                "bindings" => self.bindings(&child)?,
                _ => body.user_data = self.user_data(&child)?,
            }
        }
        self.origins.bodies.push(tag.at);
        self.scene.bodies.push(body);
        Ok(())
    }

    /// A body lists its fixtures as `<Fixtures>` IDs, or in Farseer's Version 3 layout as
    /// `<Bindings>`; the other one is an error, since dropping it would lose fixtures.
    fn layout_mismatch(&self, child: &Tag, name: &str) -> Option<super::Problem> {
        let why = match (name, self.farseer_layout()) {
            ("fixtures", true) => "a Version 3 body lists its fixtures in <Bindings>",
            ("bindings", false) => {
                "<Bindings> belongs to Version 3 files; this body lists its fixtures in <Fixtures>"
            }
            _ => return None,
        };
        Some(problem(Code::UnexpectedElement, child.at, format!("<{}> here: {why}", child.name())))
    }

    /// Version 3: `<Pair FixtureId="k" ShapeId="s"/>` children, made into fixtures once the
    /// whole file is read.
    fn bindings(&mut self, tag: &Tag) -> Parsed<()> {
        let body = self.scene.bodies.len() as u32;
        self.items(tag, "Pair", |p, pair| {
            let attrs = p.attributes(&pair)?;
            p.unknown_attributes(&pair, &attrs, &["fixtureid", "shapeid"])?;
            let id = |name: &str| match attrs.iter().find(|a| a.is(name)) {
                Some(attr) => p.attribute(&pair, attr, crate::text::id),
                None => Err(problem(
                    Code::MissingAttribute,
                    pair.at,
                    format!("<{}> has no {name} attribute", pair.name()),
                )),
            };
            let (fixture_id, shape) = (id("fixtureid")?, id("shapeid")?);
            p.origins.pairs.push(super::Pair { body, fixture_id, shape });
            p.skip(&pair)
        })
    }

    fn body_type(&mut self, tag: &Tag) -> Parsed<BodyKind> {
        let attrs = self.attributes(tag)?;
        self.unknown_attributes(tag, &attrs, &["type"])?;
        let Some(ty) = attrs.iter().find(|a| a.is("type")) else {
            return Err(problem(
                Code::MissingAttribute,
                tag.at,
                "<Body> has no Type attribute (Static, Dynamic or Kinematic)",
            ));
        };
        let value = super::trim_xml(&ty.value);
        match super::lowercase(value, &mut [0; 16]) {
            "static" => Ok(BodyKind::Static),
            "kinematic" => Ok(BodyKind::Kinematic),
            "dynamic" => Ok(BodyKind::Dynamic),
            _ => Err(problem(
                Code::UnknownType,
                ty.at,
                format!(
                    "unknown body Type \"{}\": expected Static, Dynamic or Kinematic",
                    super::shorten(value)
                ),
            )),
        }
    }

    fn mass_data(&mut self, tag: &Tag, mass: &mut MassData) -> Parsed<()> {
        let mut seen = Seen::default();
        while let Some(child) = self.child(tag)? {
            let Some((name, repeated)) = self.known(tag, &child, MASS_DATA, &mut seen)? else {
                continue;
            };
            if repeated {
                self.duplicate(tag, &child)?;
            }
            match name {
                "mass" => (mass.mass, mass.mass_given) = (self.non_negative(&child)?, true),
                "center" => (mass.center, mass.center_given) = (self.vector(&child)?, true),
                _ => (mass.inertia, mass.inertia_given) = (self.non_negative(&child)?, true),
            }
        }
        Ok(())
    }

    /// A body's `<Fixtures>`: `ID` children, checked against the fixtures after the whole
    /// file is read.
    fn fixture_ids(&mut self, tag: &Tag) -> Parsed<Range> {
        let first = self.scene.fixture_ids.len();
        self.items(tag, "ID", |p, id| {
            let (index, at) = p.id(&id)?;
            p.scene.fixture_ids.push(index);
            p.origins.fixture_ids.push(at);
            Ok(())
        })?;
        Ok(Range { first: first as u32, count: (self.scene.fixture_ids.len() - first) as u32 })
    }
}
