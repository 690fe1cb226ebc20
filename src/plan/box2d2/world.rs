//! The mapping of a scene onto Box2D 2.x (`version.rs` says where 2.3 and 2.4 differ): one pass in the order the executor creates what
//! it makes (the shapes checked first, then each body with its fixtures and mass, then the
//! joints, gears last), reporting what the engine cannot hold as it meets it.

use std::fmt;

use super::body::Body;
use super::made::Made;
use super::math::{angle, transform};
use super::version::Version;
use crate::error::Code;
use crate::plan::check::Check;
use crate::plan::container::{Object, Plan};
use crate::plan::printf::G9;
use crate::plan::range::WorkingRange;
use crate::plan::records::{PlanMass, PlanOptions};
use crate::scene::{Scene, Str, Vec2};

/// The plan of `scene` for a Box2D 2.x version.
pub(crate) fn plan(scene: &Scene, options: &PlanOptions, version: &'static Version) -> Plan {
    let mut mapper = Mapper::new(scene, options, version);
    mapper.run();
    mapper.plan
}

/// One mapping: the scene, what is planned so far, and what the engine will hold of it.
pub(super) struct Mapper<'a> {
    pub(super) scene: &'a Scene,
    pub(super) options: &'a PlanOptions,
    pub(super) version: &'static Version,
    pub(super) range: &'static WorkingRange,
    pub(super) plan: Plan,
    /// rad: what the placement adds to every body's angle.
    pub(super) placement_angle: f32,
    /// Indexed like the scene's shapes: what the engine makes of each, where it can.
    pub(super) shapes: Vec<Option<Made>>,
    /// Indexed like the scene's bodies: each created body as the joints will find it.
    pub(super) bodies: Vec<Option<Body>>,
    /// Indexed like the scene's bodies: each dynamic body's predicted mass, inertia about
    /// the centre of mass, which the checks of its joints read.
    pub(super) masses: Vec<PlanMass>,
    /// Indexed like the scene's joints: the plan joint made of each.
    pub(super) joints: Vec<Option<u32>>,
    /// Indexed like the scene's bodies: the joint that starts pulling it from far off.
    pub(super) pulled: Vec<Option<u32>>,
}

impl<'a> Mapper<'a> {
    fn new(scene: &'a Scene, options: &'a PlanOptions, version: &'static Version) -> Mapper<'a> {
        Mapper {
            scene,
            options,
            version,
            range: version.engine.working_range(),
            plan: Plan::with_capacity(
                scene.bodies().len(),
                scene.fixture_id_pool().len(),
                scene.joints().len(),
            ),
            placement_angle: angle(options.placement.q),
            shapes: Vec::new(),
            bodies: vec![None; scene.bodies().len()],
            masses: vec![PlanMass::default(); scene.bodies().len()],
            joints: vec![None; scene.joints().len()],
            pulled: vec![None; scene.bodies().len()],
        }
    }

    fn run(&mut self) {
        if !self.placement_valid() {
            let p = self.options.placement;
            self.report(
                Code::InvalidArgument,
                Object::World,
                0,
                Str::NULL,
                format_args!(
                    "the placement ({}, {}) turned by ({}, {}) is not finite, not within +-{} m \
                     or not a normalised rotation; nothing was built",
                    G9(p.p.x),
                    G9(p.p.y),
                    G9(p.q.c),
                    G9(p.q.s),
                    G9(self.range.max_length)
                ),
            );
            self.plan.set_unplaced();
            return;
        }
        self.check_gravity();
        self.report_lossy_filters();
        self.make_shapes();
        for index in 0..self.scene.bodies().len() {
            self.make_body(index as u32);
        }
        // Joints come after every body has its final mass (a spring's stiffness depends on
        // it), and gears after the joints they couple, which may come later in the file.
        let gear = |j: &crate::scene::Joint| j.kind == crate::scene::JointKind::Gear as u32;
        for index in 0..self.scene.joints().len() {
            if !gear(&self.scene.joints()[index]) {
                self.make_joint(index as u32);
            }
        }
        for index in 0..self.scene.joints().len() {
            if gear(&self.scene.joints()[index]) {
                self.make_gear(index as u32);
            }
        }
    }

    /// A check whose report names this version.
    pub(super) fn check(&self) -> Check {
        Check::new(self.version.name)
    }

    pub(super) fn report(
        &mut self,
        code: Code,
        object: Object,
        index: u32,
        name: Str,
        message: fmt::Arguments<'_>,
    ) {
        let name = self.scene.text(name);
        self.plan.report(code, object, index, name, message);
    }

    /// Reports an object found beyond the working range; false when it is.
    pub(super) fn within_range(
        &mut self,
        check: &Check,
        object: Object,
        index: u32,
        name: Str,
        owner: &str,
    ) -> bool {
        if check.passed() {
            return true;
        }
        let what = object.name().to_str().expect("object names are ASCII");
        self.report(
            Code::BeyondBox2dRange,
            object,
            index,
            name,
            format_args!("{owner}{}; {what} not created", check.problem()),
        );
        false
    }

    /// The host falls back to a gravity of its own where the file's lies beyond the range.
    fn check_gravity(&mut self) {
        let Some(gravity) = self.scene.gravity() else {
            return;
        };
        let mut check = self.check();
        check.vector("Gravity", gravity, self.range.max_acceleration, "m/s^2");
        if !check.passed() {
            self.report(
                Code::BeyondBox2dRange,
                Object::World,
                0,
                Str::NULL,
                format_args!(
                    "{}; scene_gravity gives the host's fallback instead",
                    check.problem()
                ),
            );
        }
    }

    /// A placement Box2D 2.x can take: finite, within the working range, its rotation
    /// normalised (2.4 keeps a body's angle, and the placement's rotation is added to it).
    fn placement_valid(&self) -> bool {
        let t = self.options.placement;
        let qq = t.q.c * t.q.c + t.q.s * t.q.s;
        [t.p.x, t.p.y, t.q.c, t.q.s].iter().all(|v| v.is_finite())
            && (qq - 1.0).abs() < 1e-4
            && t.p.x.abs() <= self.range.max_length
            && t.p.y.abs() <= self.range.max_length
    }

    /// A point of the scene's world frame where the placement puts it.
    pub(super) fn placed(&self, point: Vec2) -> Vec2 {
        transform(self.options.placement, point)
    }

    /// Box2D 2.x holds 16 of the scene's 32 filter bits: reports each fixture that the cut
    /// makes collide otherwise (a category bit above 16, or a mask meeting one in use).
    fn report_lossy_filters(&mut self) {
        const HIGH: u32 = 0xFFFF_0000;
        let fixtures = self.scene.fixtures();
        let high_in_use = fixtures.iter().fold(0, |bits, f| bits | (f.filter.category_bits & HIGH));
        if high_in_use == 0 {
            return;
        }
        for (index, fixture) in fixtures.iter().enumerate() {
            let filter = fixture.filter;
            if (filter.category_bits & HIGH) != 0 || (filter.mask_bits & high_in_use) != 0 {
                self.report(
                    Code::LossyFilter,
                    Object::Fixture,
                    index as u32,
                    fixture.name,
                    format_args!(
                        "category bits {} and mask bits {} reach above {}'s 16 filter bits \
                         where categories in use are; the low 16 were used, so it collides \
                         otherwise",
                        filter.category_bits, filter.mask_bits, self.version.name
                    ),
                );
            }
        }
    }
}
