//! Box2D 2.3 and 2.4 read back: each held record turned into the scene's, every derived
//! value inverted by running the plan's own arithmetic forward (`crate::plan::box2d2`) and
//! searching the floats that give back what the engine holds.
//!
//! - `shapes.rs`: a shape and its fixture's material, what the format implies of them;
//! - `bodies.rs`: a body, its MassData only where the fixtures do not give its mass, its
//!   linear velocity through the build's velocity kicks;
//! - `joints.rs`: a joint in the format's forms (a distance joint's rod, spring or rope, a
//!   wheel or line);
//! - `springs.rs`: a 2.x spring's FrequencyHz and DampingRatio, an axis that normalises.

mod bodies;
mod joints;
mod shapes;
mod springs;

#[cfg(test)]
mod tests;

pub(super) use bodies::body;
pub(super) use joints::joint;
pub(super) use shapes::{fixture, shape};
