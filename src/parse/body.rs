//! `<Body Type="...">`: state, flags, mass override and fixture IDs.

use super::{Element, Reader, Seen, Tag, attributes, elements};
use crate::arena::Pair;
use crate::error::{Code, Parsed, problem};
use crate::scene::{Body, BodyKind, MassData, Object, Range};

elements! {
    enum BodyChild {
        Name,
        Active,
        AllowSleep,
        Awake,
        Bullet,
        FixedRotation,
        Angle,
        AngularDamping,
        AngularVelocity,
        LinearDamping,
        LinearVelocity,
        Position,
        InertiaScale,
        GravityScale,
        MassData,
        Fixtures,
        UserData,
        Bindings,
        Tag,
    }
}

elements! {
    enum MassChild { Mass, Center, Inertia }
}

impl<'a> Reader<'a> {
    pub(super) fn body(&mut self, tag: &Tag) -> Parsed<()> {
        self.begin_object(Object::Body(self.arena.scene.bodies.len() as u32));
        let origin = self.spot(tag.at);
        let mut body = Body::new(self.body_type(tag)?);
        let mut name_str = None;
        let mut seen = Seen::default();
        let mut child = Tag::slot();
        while self.tok.child(tag, &mut child)? {
            let Some((name, repeated)) = self.known(tag, &child, &mut seen)? else {
                continue;
            };
            if repeated && matches!(name, BodyChild::Fixtures | BodyChild::Bindings) {
                return Err(self.tok.duplicate_container(tag, &child));
            }
            if let Some(problem) = self.layout_mismatch(&child, name) {
                return Err(problem);
            }
            if repeated {
                self.duplicate(tag, &child)?;
            }
            match name {
                BodyChild::Name => name_str = Some(self.string(&child)?),
                BodyChild::Active => body.active = self.boolean(&child)?,
                BodyChild::AllowSleep => body.allow_sleep = self.boolean(&child)?,
                BodyChild::Awake => body.awake = self.boolean(&child)?,
                BodyChild::Bullet => body.bullet = self.boolean(&child)?,
                BodyChild::FixedRotation => body.fixed_rotation = self.boolean(&child)?,
                BodyChild::Angle => body.angle = self.radians(&child)?,
                // Negative damping is not an error of the format; the Box2D adapter, whose
                // engine asserts against it, reports it and uses 0.
                BodyChild::AngularDamping => body.angular_damping = self.float(&child)?,
                BodyChild::AngularVelocity => body.angular_velocity = self.float(&child)?,
                BodyChild::LinearDamping => body.linear_damping = self.float(&child)?,
                BodyChild::LinearVelocity => body.linear_velocity = self.vector(&child)?,
                BodyChild::Position => body.position = self.vector(&child)?,
                BodyChild::InertiaScale => body.inertia_scale = self.float(&child)?,
                BodyChild::GravityScale => {
                    self.newer_construct(child.at, "<GravityScale>")?;
                    body.gravity_scale = self.float(&child)?;
                }
                BodyChild::MassData => {
                    let mass = &mut body.mass_data;
                    self.within(BodyChild::MassData.name(), |p| p.mass_data(&child, mass))?
                }
                BodyChild::Fixtures => body.fixtures = self.fixture_ids(&child)?,
                BodyChild::Bindings => self.bindings(&child)?,
                BodyChild::UserData => body.user_data = self.user_data(&child)?,
                BodyChild::Tag => match self.arena.tag_is_user_data() {
                    true => body.user_data = self.tagged_user_data(&child)?,
                    false => self.unknown(tag, &child, &[])?,
                },
            }
        }
        self.end_object();
        self.arena.origins.bodies.push(origin);
        self.arena.scene.push_body(body, name_str);
        Ok(())
    }

    /// A body lists its fixtures as `<Fixtures>` IDs, or in Farseer's Version 3 layout as
    /// `<Bindings>`; the other one is an error, since dropping it would lose fixtures.
    fn layout_mismatch(&self, child: &Tag, name: BodyChild) -> Option<super::Problem> {
        let why = match (name, self.arena.farseer_layout()) {
            (BodyChild::Fixtures, true) => "a Version 3 body lists its fixtures in <Bindings>",
            (BodyChild::Bindings, false) => {
                "<Bindings> belongs to Version 3 files; this body lists its fixtures in <Fixtures>"
            }
            _ => return None,
        };
        Some(problem(Code::UnexpectedElement, child.at, format!("<{}> here: {why}", child.name())))
    }

    /// Version 3: `<Pair FixtureId="f" ShapeId="s"/>` children, made into fixtures once the
    /// whole file is read. Both are positions in their containers.
    fn bindings(&mut self, tag: &Tag) -> Parsed<()> {
        let body = self.arena.scene.bodies.len() as u32;
        self.items(tag, "Pair", |p, pair| {
            let attrs = attributes!(p, pair, &["FixtureId", "ShapeId"]);
            let id = |name: &str| match attrs.iter().find(|a| a.is(name)) {
                Some(attr) => p.tok.attribute(pair, attr, crate::text::id),
                None => Err(problem(
                    Code::MissingAttribute,
                    pair.at,
                    format!("<{}> has no {name} attribute", pair.name()),
                )),
            };
            let (fixture, shape) = (id("fixtureid")?, id("shapeid")?);
            let (fixture, shape) = ((fixture.0, p.spot(fixture.1)), (shape.0, p.spot(shape.1)));
            p.arena.origins.pairs.push(Pair { body, fixture, shape });
            p.tok.skip(pair)
        })
    }

    fn body_type(&mut self, tag: &Tag) -> Parsed<BodyKind> {
        let known: &[&str] =
            if self.arena.id_is_informational() { &["Type", "Id"] } else { &["Type"] };
        let attrs = attributes!(self, tag, known);
        self.arena.origins.signs.ids |= known.len() > 1 && attrs.iter().any(|a| a.is("id"));
        let Some(ty) = attrs.iter().find(|a| a.is("type")) else {
            return Err(problem(
                Code::MissingAttribute,
                tag.at,
                "<Body> has no Type attribute (Static, Dynamic or Kinematic)",
            ));
        };
        let value = super::trim_xml(&ty.value);
        let kind = match super::lowercase(value, &mut [0; 16]) {
            b"static" => Ok(BodyKind::Static),
            b"kinematic" => Ok(BodyKind::Kinematic),
            b"dynamic" => Ok(BodyKind::Dynamic),
            _ => Err(problem(
                Code::UnknownType,
                ty.at,
                format!(
                    "unknown body Type \"{}\"{}: expected Static, Dynamic or Kinematic",
                    super::shorten(value),
                    super::did_you_mean(value, &["Static", "Dynamic", "Kinematic"])
                ),
            )),
        };
        // Every kind of body reads the same elements: the reading goes on as if Static.
        self.recovered(kind, BodyKind::Static)
    }

    fn mass_data(&mut self, tag: &Tag, mass: &mut MassData) -> Parsed<()> {
        let mut seen = Seen::default();
        let mut child = Tag::slot();
        while self.tok.child(tag, &mut child)? {
            let Some((name, repeated)) = self.known(tag, &child, &mut seen)? else {
                continue;
            };
            if repeated {
                self.duplicate(tag, &child)?;
            }
            match name {
                MassChild::Mass => {
                    (mass.mass, mass.mass_given) = (self.non_negative(&child)?, true)
                }
                MassChild::Center => {
                    (mass.center, mass.center_given) = (self.vector(&child)?, true)
                }
                MassChild::Inertia => {
                    (mass.inertia, mass.inertia_given) = (self.non_negative(&child)?, true)
                }
            }
        }
        Ok(())
    }

    /// A body's `<Fixtures>`: `ID` children, checked against the fixtures after the whole
    /// file is read.
    fn fixture_ids(&mut self, tag: &Tag) -> Parsed<Range> {
        let first = self.arena.scene.fixture_ids.len();
        self.items(tag, "ID", |p, id| {
            let (index, at) = p.id(id)?;
            p.arena.scene.fixture_ids.push(index);
            let origin = p.spot(at);
            p.arena.origins.fixture_ids.push(origin);
            Ok(())
        })?;
        Ok(Range::between(first, self.arena.scene.fixture_ids.len()))
    }
}
