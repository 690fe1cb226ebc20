//! The plan stage, after the frozen scene: what each Box2D version can be given. A plan
//! (`container.rs`) holds every body, shape and joint as one version's definitions want
//! them and the reports of what it cannot hold (`records.rs`); `make.rs` hands the scene to
//! the module of the version asked for (`box2d2/` for Box2D 2.4, `box2d3/` for v3.1 and
//! v3.2, each with its engine's arithmetic repeated to the bit); `gravity.rs` is the gravity
//! a world is made with. `range.rs` is the working range, one measured table per engine
//! version, which the executors in C, C++ and Python also read; `printf.rs` spells numbers
//! in reports as C does.

#![forbid(unsafe_code)]
// The checks are negated comparisons, `!(value <= bound)`, so that a NaN fails every one of
// them, as it fails the engine's; and Box2D's constants (its pi, not Rust's) are written as
// Box2D writes them.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::excessive_precision, clippy::approx_constant)]

pub(crate) mod box2d2;
pub(crate) mod box2d3;
mod check;
mod container;
mod gravity;
mod make;
pub(crate) mod math;
pub(crate) mod printf;
mod range;
mod records;

pub use container::{Object, Plan};
pub use gravity::world_gravity;
pub use make::make;
pub use range::{Engine, WorkingRange};
pub use records::*;
