//! The builder, and the records at their defaults for it.

use super::{
    ErrorInfo, RawBodyKind, RawJointKind, RawShapeKind, SceneHandle, arg_slice, arg_str, fallible,
    guard, scene_into, simple_error,
};
use crate::Builder;
use crate::error::{Code, Error};
use crate::scene::{Body, BodyKind, Fixture, Joint, JointKind, Shape, ShapeKind, Str};
use crate::scene::{UserData, Vec2};

/// A scene under construction (opaque): `b2s_builder_new`, then `b2s_builder_add_*`, then
/// `b2s_builder_finish` (or `b2s_builder_free` to abandon it). Not for use from two
/// threads at once.
pub struct BuilderHandle {
    builder: Builder,
}

/// A new, empty scene builder. Never NULL.
#[unsafe(no_mangle)]
pub extern "C" fn b2s_builder_new() -> *mut BuilderHandle {
    Box::into_raw(Box::new(BuilderHandle { builder: Builder::new() }))
}

/// Abandons a builder and everything added to it. NULL is ignored.
///
/// # Safety
/// `builder` is NULL or a builder that was not finished or freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_free(builder: *mut BuilderHandle) {
    guard(
        || (),
        || {
            if !builder.is_null() {
                // SAFETY: made by Box::into_raw in b2s_builder_new, freed once by contract.
                drop(unsafe { Box::from_raw(builder) });
            }
        },
    )
}

/// Reads an optional NUL-terminated string of a record.
///
/// # Safety
/// `s` is NULL or NUL-terminated.
unsafe fn optional_str<'a>(s: Str, what: &str) -> Result<Option<&'a str>, Error> {
    match s.is_null() {
        true => Ok(None),
        // SAFETY: by the caller's contract.
        false => unsafe { arg_str(s.0, what) }.map(Some),
    }
}

/// Runs one addition to a builder: checks the pointers, stores the new index.
///
/// # Safety
/// `builder` is NULL or a live builder; `record` NULL or valid; `out_index` NULL or
/// writable; `error` NULL or writable.
unsafe fn add<T>(
    builder: *mut BuilderHandle,
    record: *const T,
    out_index: *mut u32,
    error: *mut ErrorInfo,
    add: impl FnOnce(&mut Builder, &T) -> Result<u32, Error>,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let (handle, record) = unsafe { (builder.as_mut(), record.as_ref()) };
        let handle = handle.ok_or_else(|| simple_error(Code::NullArgument, "builder is NULL"))?;
        let record =
            record.ok_or_else(|| simple_error(Code::NullArgument, "the record is NULL"))?;
        let index = add(&mut handle.builder, record)?;
        // SAFETY: by the caller's contract.
        if let Some(out) = unsafe { out_index.as_mut() } {
            *out = index;
        }
        Ok(())
    })
}

/// Sets the scene's gravity; NULL means none (the host decides).
///
/// # Safety
/// `builder` is NULL or a live builder; `gravity` NULL or valid; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_set_gravity(
    builder: *mut BuilderHandle,
    gravity: *const Vec2,
    error: *mut ErrorInfo,
) -> Code {
    fallible(error, || {
        // SAFETY: by the caller's contract.
        let handle = unsafe { builder.as_mut() }
            .ok_or_else(|| simple_error(Code::NullArgument, "builder is NULL"))?;
        // SAFETY: by the caller's contract.
        handle.builder.set_gravity(unsafe { gravity.as_ref() }.copied())
    })
}

/// Adds user data; stores its index in `*out_index` (when not NULL), for the `user_data`
/// field of fixtures, bodies and joints added later. `raw` (XML content, kept verbatim)
/// wins; without it, `type_name` and `value` are written in the editor's form. The
/// stored `type_name` and `value` are those the loader would find in the raw XML.
///
/// # Safety
/// `builder` is NULL or a live builder; `user_data` NULL or valid, its strings NULL or
/// NUL-terminated; `out_index` and `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_user_data(
    builder: *mut BuilderHandle,
    user_data: *const UserData,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, user_data, out_index, error, |b, u| {
            let raw = optional_str(u.raw, "raw")?;
            let (type_name, value) =
                (optional_str(u.type_name, "type_name")?, optional_str(u.value, "value")?);
            b.add_user_data(raw, type_name, value)
        })
    }
}

/// Adds a shape (its `name` is copied; its `vertices` range is ignored: the `count`
/// vertices at `vertices` are copied instead) and stores its index in `*out_index`.
/// Refused with the loader's codes (`bad-radius`, `bad-vertex-count`,
/// `degenerate-polygon`, ...); the message names the shape's index.
///
/// # Safety
/// `builder` is NULL or a live builder; `shape` NULL or valid, its name NULL or
/// NUL-terminated; `vertices` NULL (with `count` 0) or `count` readable vectors;
/// `out_index` and `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_shape(
    builder: *mut BuilderHandle,
    shape: *const Shape,
    vertices: *const Vec2,
    count: u32,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, shape, out_index, error, |b, s| {
            let vertices = arg_slice(vertices, count as usize, "vertices")?;
            b.add_shape(s, optional_str(s.name, "name")?, vertices)
        })
    }
}

/// Adds a fixture on a shape added before; stores its index in `*out_index`.
///
/// # Safety
/// As for `b2s_builder_add_shape`, without vertices.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_fixture(
    builder: *mut BuilderHandle,
    fixture: *const Fixture,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, fixture, out_index, error, |b, f| {
            b.add_fixture(f, optional_str(f.name, "name")?)
        })
    }
}

/// Adds a body (its `fixtures` range is ignored: the `count` fixture indices at
/// `fixtures` are copied instead, each of a fixture added before); stores its index.
///
/// # Safety
/// As for `b2s_builder_add_shape`, with `fixtures` NULL (with `count` 0) or `count`
/// readable indices.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_body(
    builder: *mut BuilderHandle,
    body: *const Body,
    fixtures: *const u32,
    count: u32,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, body, out_index, error, |b, body| {
            let fixtures = arg_slice(fixtures, count as usize, "fixtures")?;
            b.add_body(body, optional_str(body.name, "name")?, fixtures)
        })
    }
}

/// Adds a joint between bodies added before (a gear: after the two joints it couples);
/// stores its index. Fields its kind does not have take that kind's defaults.
///
/// # Safety
/// As for `b2s_builder_add_fixture`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_add_joint(
    builder: *mut BuilderHandle,
    joint: *const Joint,
    out_index: *mut u32,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: by the caller's contract.
    unsafe {
        add(builder, joint, out_index, error, |b, j| b.add_joint(j, optional_str(j.name, "name")?))
    }
}

/// Finishes the builder into an ordinary immutable scene, stored in `*out_scene` (free it
/// with `b2s_scene_free`). The builder is freed in every case.
///
/// # Safety
/// `builder` is NULL or a builder that was not finished or freed yet; `out_scene` NULL or
/// writable; `error` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_builder_finish(
    builder: *mut BuilderHandle,
    out_scene: *mut *mut SceneHandle,
    error: *mut ErrorInfo,
) -> Code {
    // SAFETY: made by Box::into_raw in b2s_builder_new; taken once by contract.
    let handle = (!builder.is_null()).then(|| unsafe { Box::from_raw(builder) });
    // SAFETY: by the caller's contract.
    unsafe {
        scene_into(out_scene, error, || match handle {
            Some(handle) => Ok(handle.builder.finish()),
            None => Err(simple_error(Code::NullArgument, "builder is NULL")),
        })
    }
}

/// Writes into `*out` a shape of `kind` with every field at its default. Returns
/// `B2S_CODE_INVALID_ARGUMENT` for an unknown kind, `B2S_CODE_NULL_ARGUMENT` for a NULL
/// `out`.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_shape_default(kind: RawShapeKind, out: *mut Shape) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, ShapeKind::try_from(kind).ok().map(Shape::new)) }
}

/// Writes into `*out` a fixture with every field at its default.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_fixture_default(out: *mut Fixture) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, Some(Fixture::default())) }
}

/// Writes into `*out` a body of `kind` with every field at its default. Returns
/// `B2S_CODE_INVALID_ARGUMENT` for an unknown kind.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_body_default(kind: RawBodyKind, out: *mut Body) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, BodyKind::try_from(kind).ok().map(Body::new)) }
}

/// Writes into `*out` a joint of `kind` with every field at the default of that kind
/// (`docs/format.md` lists them). Returns `B2S_CODE_INVALID_ARGUMENT` for an unknown kind.
///
/// # Safety
/// `out` is NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn b2s_joint_default(kind: RawJointKind, out: *mut Joint) -> Code {
    // SAFETY: by the caller's contract.
    unsafe { write_default(out, JointKind::try_from(kind).ok().map(Joint::new)) }
}

/// # Safety
/// `out` is NULL or writable.
unsafe fn write_default<T>(out: *mut T, value: Option<T>) -> Code {
    guard(
        || Code::Internal,
        || match (out.is_null(), value) {
            (true, _) => Code::NullArgument,
            (false, None) => Code::InvalidArgument,
            (false, Some(value)) => {
                // SAFETY: not NULL, writable by the caller's contract.
                unsafe { out.write(value) };
                Code::Ok
            }
        },
    )
}
