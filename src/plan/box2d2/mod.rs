//! Box2D 2.x (2.3 as pybox2d holds it, and 2.4): the engine's own arithmetic, repeated
//! operation for operation in `f32` so that what a plan predicts (a body's mass, a
//! spring's stiffness, where a joint starts) is the engine's to the bit, and the mapping of
//! a scene onto its definitions.

pub(crate) mod bodies;
pub(crate) mod body;
pub(crate) mod body_mass;
mod joint_checks;
mod joints;
mod made;
pub(crate) mod math;
pub(crate) mod polygon;
pub(crate) mod shape_mass;
mod shapes;
pub(crate) mod stiffness;
pub(crate) mod version;
mod world;

pub(crate) use version::Version;
pub(crate) use world::plan;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_23;
