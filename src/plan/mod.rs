//! The plan stage, after the frozen scene: what each Box2D version can be given. A plan
//! (`container.rs`) holds every body, shape and joint as one version's definitions want
//! them and the reports of what it cannot hold (`records.rs`); `make.rs` hands the scene to
//! the module of the version asked for. `range.rs` is the working range, one measured table
//! per engine version, which the executors in C, C++ and Python also read; `box2d2/` is
//! Box2D 2.x's (its arithmetic and its mapping); `printed.rs` spells floats in reports as C
//! does.

#![forbid(unsafe_code)]

mod box2d2;
mod container;
mod make;
mod printed;
mod range;
mod records;

pub use container::{Object, Plan};
pub use make::make;
pub use range::{Engine, WorkingRange};
pub use records::*;
