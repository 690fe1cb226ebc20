//! Box2D v3.1 and v3.2 on the way back: a held body, shape or joint as the scene's, each
//! inverse searching the value whose forward computation, the plan's own
//! (`crate::plan::box2d3`), gives back what the engine holds, and what the format cannot
//! hold said through the pass's `Say`. `version.rs` holds what the two versions read back
//! differently, beside the plan's; `shapes.rs` the shapes, chains and filters; `bodies.rs`
//! the bodies and the one report of the rotations no angle gives; `joints.rs` the joints
//! and their frames.

mod bodies;
mod joints;
mod shapes;
mod version;

#[cfg(test)]
mod tests;

pub(super) use self::bodies::{body, turned};
pub(super) use self::joints::joint;
pub(super) use self::shapes::{chain_length, fixture, shape};
