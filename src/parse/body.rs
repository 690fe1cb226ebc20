//! `<Body Type="...">`: state, flags, mass override and fixture IDs.

use super::{Parsed, Parser, Seen, Tag, problem};
use crate::error::Code;
use crate::scene::{Body, BodyKind, MassData, Range};

const BODY: &[&str] = &[
    "name", "active", "allowsleep", "awake", "bullet", "fixedrotation", "angle",
    "angulardamping", "angularvelocity", "lineardamping", "linearvelocity", "position",
    "inertiascale", "gravityscale", "massdata", "fixtures", "userdata",
];
const MASS_DATA: &[&str] = &["mass", "center", "inertia"];

impl<'a> Parser<'a> {
    pub(super) fn body(&mut self, tag: Tag<'a>) -> Parsed<()> {
        let mut body = Body::new(self.body_type(&tag)?);
        let mut seen = Seen::default();
        while let Some(child) = self.child(&tag)? {
            let Some((name, repeated)) = self.known(&tag, &child, BODY, &mut seen)? else {
                continue;
            };
            if repeated && name == "fixtures" {
                return Err(self.duplicate_container(&tag, &child));
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
                // Box2D asserts that damping is not negative.
                "angulardamping" => body.angular_damping = self.non_negative(&child)?,
                "angularvelocity" => body.angular_velocity = self.float(&child)?,
                "lineardamping" => body.linear_damping = self.non_negative(&child)?,
                "linearvelocity" => body.linear_velocity = self.vector(&child)?,
                "position" => body.position = self.vector(&child)?,
                "inertiascale" => body.inertia_scale = self.float(&child)?,
                "gravityscale" => {
                    self.newer_construct(child.at, "<GravityScale>")?;
                    body.gravity_scale = self.float(&child)?;
                }
                "massdata" => self.mass_data(&child, &mut body.mass_data)?,
                "fixtures" => body.fixtures = self.fixture_ids(&child)?,
                _ => body.user_data = self.user_data(&child)?,
            }
        }
        self.origins.bodies.push(tag.at);
        self.scene.bodies.push(body);
        Ok(())
    }

    fn body_type(&mut self, tag: &Tag<'a>) -> Parsed<BodyKind> {
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
        match value.to_ascii_lowercase().as_str() {
            "static" => Ok(BodyKind::Static),
            "kinematic" => Ok(BodyKind::Kinematic),
            "dynamic" => Ok(BodyKind::Dynamic),
            _ => Err(problem(
                Code::UnknownType,
                ty.at,
                format!("unknown body Type \"{}\": expected Static, Dynamic or Kinematic", super::shorten(value)),
            )),
        }
    }

    fn mass_data(&mut self, tag: &Tag<'a>, mass: &mut MassData) -> Parsed<()> {
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
    fn fixture_ids(&mut self, tag: &Tag<'a>) -> Parsed<Range> {
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
