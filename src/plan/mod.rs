//! The plan stage, after the frozen scene: what each Box2D version can be given. A plan
//! (`container.rs`) holds every body, shape and joint as one version's definitions want
//! them and the reports of what it cannot hold (`records.rs`); `make.rs` hands the scene to
//! the module of the version asked for (`box2d3/` for v3.1 and v3.2); `gravity.rs` is the
//! gravity a world is made with. `range.rs` is the working range, one measured table per
//! engine version, which the executors in C, C++ and Python also read.

#![forbid(unsafe_code)]

mod box2d3;
mod container;
mod gravity;
mod make;
mod printf;
mod range;
mod records;

pub use container::{Object, Plan};
pub use gravity::world_gravity;
pub use make::make;
pub use range::{Engine, WorkingRange};
pub use records::*;
