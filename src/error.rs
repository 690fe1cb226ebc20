//! Result codes, diagnostics and the load error.
#![forbid(unsafe_code)]

use std::ffi::CStr;
use std::fmt;

/// Every result, error and warning code. 0 is success. The numbers are part of the ABI:
/// codes are only ever appended, never renumbered. `b2s_code_name` gives its
/// kebab-case name, the one `docs/format.md` lists.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Code {
    /// Success.
    Ok = 0,

    // Misuse of the API and the environment.
    /// A required pointer argument was NULL.
    NullArgument = 1,
    /// An argument was out of its range (an unknown enum value, a bad option).
    InvalidArgument = 2,
    /// The file could not be read.
    Io = 3,
    /// A bug in box2scene: a panic was caught at the C boundary.
    Internal = 4,

    // The bytes and the XML.
    /// Bytes that are not UTF-8 in a file read as UTF-8.
    InvalidUtf8 = 10,
    /// A NUL character in the text.
    NulByte = 11,
    /// An XML declaration names an encoding other than UTF-8 or UTF-16.
    UnsupportedEncoding = 12,
    /// A `<!DOCTYPE`: refused so that no entity is ever expanded or fetched.
    DoctypeForbidden = 13,
    /// XML that does not parse: mismatched or unclosed tags, a second root, text after
    /// the root, a bad character reference.
    MalformedXml = 14,
    /// One attribute twice on one start tag (names compare without regard to case).
    DuplicateAttribute = 15,
    /// One of the load limits of `b2s_load_options` was exceeded; the message names it.
    LimitExceeded = 16,
    /// Non-blank text where only elements belong.
    UnexpectedText = 17,

    // The structure of the scene.
    /// The root element is not `World`.
    NotAScene = 20,
    /// A `Version` other than 1, 2 or 3.
    UnsupportedVersion = 21,
    /// A container (`Shapes`, `Vertices`, ...) appears twice in one object.
    DuplicateContainer = 22,
    /// A child a container cannot hold (a `Body` inside `Shapes`).
    UnexpectedElement = 23,
    /// A mandatory attribute (a `Type`) is absent.
    MissingAttribute = 24,
    /// A mandatory element (a fixture's `Shape`, a joint's `BodyA`) is absent.
    MissingElement = 25,
    /// An unknown shape or body `Type`.
    UnknownType = 26,
    /// A joint `Type` box2scene does not know (`Mouse`, a misspelling); also a built
    /// joint of the unsupported kind that has no text to write.
    UnsupportedJointType = 27,

    // Values.
    /// Text that is not an integer.
    InvalidInt = 30,
    /// Text that is not a number.
    InvalidFloat = 31,
    /// A number written with a decimal comma (`0,5`), as a writer in a comma locale does.
    FloatDecimalComma = 32,
    /// NaN, an infinity, or a literal too large for a 32-bit float.
    NonFiniteFloat = 33,
    /// Text that is not `true`, `false`, `1` or `0`.
    InvalidBool = 34,
    /// Text that is not two numbers.
    InvalidVector2 = 35,
    /// An ID that is not a non-negative integer.
    InvalidId = 36,
    /// Filter bits that are not a non-negative decimal or `0x` hexadecimal number.
    InvalidBits = 37,
    /// An integer outside its type's range (a 32-bit int, a 16-bit group index).
    OutOfRange = 38,

    // Meaning.
    /// An ID that names an object its container does not have.
    IdOutOfRange = 40,
    /// A circle radius that is not positive.
    BadRadius = 41,
    /// A polygon with fewer than 2 or more than 8 vertices, a chain with fewer than 2 (a
    /// loop: 3).
    BadVertexCount = 42,
    /// A polygon with (nearly) no area, or a two-vertex polygon whose ends (nearly) meet.
    DegeneratePolygon = 43,
    /// An edge shorter than Box2D's linear slop (5 mm).
    DegenerateEdge = 44,
    /// A chain with two consecutive vertices closer than Box2D's linear slop (5 mm).
    DegenerateChain = 45,
    /// A negative value where only zero or more makes sense (density, a force, a length).
    NegativeValue = 46,
    /// A joint whose two bodies are the same body.
    JointSelfReference = 47,
    /// A gear joint that does not name two revolute or prismatic joints other than itself.
    BadGearJoint = 48,
    /// A lower limit above its upper limit, with the limit enabled.
    BadLimit = 49,
    /// A zero-length joint axis.
    ZeroAxis = 50,
    /// A pulley ratio that is not positive.
    BadRatio = 51,
    /// No longer reported: a Version 3 fixture's `Id` is informational (its Pairs name
    /// fixtures by position), so Ids may repeat. The number stays reserved.
    DuplicateId = 52,

    // Warnings.
    /// A file without `Version`: read as the original editor's 2010 files.
    LegacyUnversioned = 100,
    /// A Version 2 construct in a file that says Version 1.
    ConstructNewerThanVersion = 101,
    /// A value element given twice in one object; the last one counts.
    DuplicateElement = 102,
    /// An element or attribute box2scene does not know; skipped, and kept for the writer.
    UnknownElement = 103,
    /// `World` without one of `Shapes`, `Fixtures`, `Bodies`, `Joints`; read as empty.
    MissingContainer = 104,
    /// No longer reported: filter bits are kept whole, 32 of them (the Box2D 2.4 adapter
    /// reports `lossy-filter` where its 16 change what collides). The number stays reserved.
    FilterBitsTruncated = 105,
    /// Polygon vertices that are not convex and counter-clockwise; Box2D takes their hull.
    PolygonNotConvexCcw = 106,
    /// A dynamic body with a fixture of zero density and no `MassData` mass.
    DynamicBodyZeroDensity = 107,
    /// A Farseer `Angle` or `Slider` joint, kept as a joint of the unsupported kind.
    FarseerOnlyJoint = 108,
    /// A Farseer line joint with a spring: read as a wheel joint.
    LineJointIsWheel = 109,
    /// The file had more warnings than a scene keeps; this last one counts the rest.
    WarningsTruncated = 110,
    /// A joint whose bodies the file places further from satisfied than Box2D's slop
    /// (0.005 m, 2 degrees): the message says how far, in metres or radians.
    JointStartsViolated = 111,
    /// A revolute joint's `LowerAngle` or `UpperAngle`, or a body's `Angle`, that is a whole
    /// number beyond a full turn (2 pi) and within one in degrees (360): degrees written
    /// where radians are meant (`-45` for -pi/4); read as radians.
    AngleInDegrees = 112,

    // What the Box2D adapter reports.
    /// A line joint's linear motor: Box2D 2.4 has none; the motor is left off.
    LossyLineMotor = 200,
    /// A joint Box2D cannot represent (Farseer-only kinds); it was skipped.
    SkippedJoint = 201,
    /// An object that names another that could not be created; it was skipped.
    SkippedDependent = 202,
    /// A MassData whose inertia about the body origin is below mass * |center|^2 leaves no
    /// positive inertia about the centre of mass, which Box2D rejects; the mass computed
    /// from the fixtures was kept.
    InconsistentMassData = 203,
    /// A value beyond the range in which Box2D 2.4 stays finite (`docs/box2d.md`
    /// gives the bounds); the object, and what depends on it, was skipped.
    BeyondBox2dRange = 204,
    /// Capturing a live world: a value was written as the nearest the format can hold,
    /// not exactly (the message says what and by how much).
    LossyCapture = 205,
    /// A shape Box2D v3 holds only approximately: a ghost vertex it needs was extrapolated,
    /// a polygon's Centroid it cannot take, a chain's sensor flag it has no form for.
    LossyShape = 206,
    /// A joint value Box2D v3 clamps or has no field for: a revolute limit or reference
    /// angle past its range, a length under its minimum, a friction joint's anchors.
    LossyJoint = 207,
    /// Filter bits Box2D 2.4 cannot hold in its 16 where that changes what collides: a
    /// category above bit 16 in use, or a mask whose bits above 16 meet such a category.
    LossyFilter = 208,
    /// A body state Box2D v3 cannot hold as the file gives it: `Awake` false with
    /// `AllowSleep` false (v3 creates such a body awake).
    LossyBody = 209,

    // Writing.
    /// A scene holds what the dialect it is written in cannot (a gear joint for a Farseer
    /// reader, a chain for Farseer 3.3.1, kept comments): the message names the object.
    DialectCannotHold = 300,
}

impl Code {
    /// Every code, in numeric order.
    pub const ALL: &[Code] = &[
        Code::Ok,
        Code::NullArgument,
        Code::InvalidArgument,
        Code::Io,
        Code::Internal,
        Code::InvalidUtf8,
        Code::NulByte,
        Code::UnsupportedEncoding,
        Code::DoctypeForbidden,
        Code::MalformedXml,
        Code::DuplicateAttribute,
        Code::LimitExceeded,
        Code::UnexpectedText,
        Code::NotAScene,
        Code::UnsupportedVersion,
        Code::DuplicateContainer,
        Code::UnexpectedElement,
        Code::MissingAttribute,
        Code::MissingElement,
        Code::UnknownType,
        Code::UnsupportedJointType,
        Code::InvalidInt,
        Code::InvalidFloat,
        Code::FloatDecimalComma,
        Code::NonFiniteFloat,
        Code::InvalidBool,
        Code::InvalidVector2,
        Code::InvalidId,
        Code::InvalidBits,
        Code::OutOfRange,
        Code::IdOutOfRange,
        Code::BadRadius,
        Code::BadVertexCount,
        Code::DegeneratePolygon,
        Code::DegenerateEdge,
        Code::DegenerateChain,
        Code::NegativeValue,
        Code::JointSelfReference,
        Code::BadGearJoint,
        Code::BadLimit,
        Code::ZeroAxis,
        Code::BadRatio,
        Code::DuplicateId,
        Code::LegacyUnversioned,
        Code::ConstructNewerThanVersion,
        Code::DuplicateElement,
        Code::UnknownElement,
        Code::MissingContainer,
        Code::FilterBitsTruncated,
        Code::PolygonNotConvexCcw,
        Code::DynamicBodyZeroDensity,
        Code::FarseerOnlyJoint,
        Code::LineJointIsWheel,
        Code::WarningsTruncated,
        Code::JointStartsViolated,
        Code::AngleInDegrees,
        Code::LossyLineMotor,
        Code::SkippedJoint,
        Code::SkippedDependent,
        Code::InconsistentMassData,
        Code::BeyondBox2dRange,
        Code::LossyCapture,
        Code::LossyShape,
        Code::LossyJoint,
        Code::LossyFilter,
        Code::LossyBody,
        Code::DialectCannotHold,
    ];

    /// The kebab-case name of the code (`"id-out-of-range"`).
    pub fn name(self) -> &'static str {
        self.c_name().to_str().expect("code names are ASCII")
    }

    /// [`Code::name`] NUL-terminated, for C.
    pub const fn c_name(self) -> &'static CStr {
        match self {
            Code::Ok => c"ok",
            Code::NullArgument => c"null-argument",
            Code::InvalidArgument => c"invalid-argument",
            Code::Io => c"io-error",
            Code::Internal => c"internal-error",
            Code::InvalidUtf8 => c"invalid-utf8",
            Code::NulByte => c"nul-byte",
            Code::UnsupportedEncoding => c"unsupported-encoding",
            Code::DoctypeForbidden => c"doctype-forbidden",
            Code::MalformedXml => c"malformed-xml",
            Code::DuplicateAttribute => c"duplicate-attribute",
            Code::LimitExceeded => c"limit-exceeded",
            Code::UnexpectedText => c"unexpected-text",
            Code::NotAScene => c"not-a-scene",
            Code::UnsupportedVersion => c"unsupported-version",
            Code::DuplicateContainer => c"duplicate-container",
            Code::UnexpectedElement => c"unexpected-element",
            Code::MissingAttribute => c"missing-attribute",
            Code::MissingElement => c"missing-element",
            Code::UnknownType => c"unknown-type",
            Code::UnsupportedJointType => c"unsupported-joint-type",
            Code::InvalidInt => c"invalid-int",
            Code::InvalidFloat => c"invalid-float",
            Code::FloatDecimalComma => c"float-decimal-comma",
            Code::NonFiniteFloat => c"non-finite-float",
            Code::InvalidBool => c"invalid-bool",
            Code::InvalidVector2 => c"invalid-vector2",
            Code::InvalidId => c"invalid-id",
            Code::InvalidBits => c"invalid-bits",
            Code::OutOfRange => c"out-of-range",
            Code::IdOutOfRange => c"id-out-of-range",
            Code::BadRadius => c"bad-radius",
            Code::BadVertexCount => c"bad-vertex-count",
            Code::DegeneratePolygon => c"degenerate-polygon",
            Code::DegenerateEdge => c"degenerate-edge",
            Code::DegenerateChain => c"degenerate-chain",
            Code::NegativeValue => c"negative-value",
            Code::JointSelfReference => c"joint-self-reference",
            Code::BadGearJoint => c"bad-gear-joint",
            Code::BadLimit => c"bad-limit",
            Code::ZeroAxis => c"zero-axis",
            Code::BadRatio => c"bad-ratio",
            Code::DuplicateId => c"duplicate-id",
            Code::LegacyUnversioned => c"legacy-unversioned",
            Code::ConstructNewerThanVersion => c"construct-newer-than-version",
            Code::DuplicateElement => c"duplicate-element",
            Code::UnknownElement => c"unknown-element",
            Code::MissingContainer => c"missing-container",
            Code::FilterBitsTruncated => c"filter-bits-truncated",
            Code::PolygonNotConvexCcw => c"polygon-not-convex-ccw",
            Code::DynamicBodyZeroDensity => c"dynamic-body-zero-density",
            Code::FarseerOnlyJoint => c"farseer-only-joint",
            Code::LineJointIsWheel => c"line-joint-is-wheel",
            Code::WarningsTruncated => c"warnings-truncated",
            Code::JointStartsViolated => c"joint-starts-violated",
            Code::AngleInDegrees => c"angle-in-degrees",
            Code::LossyLineMotor => c"lossy-line-motor",
            Code::SkippedJoint => c"skipped-joint",
            Code::SkippedDependent => c"skipped-dependent",
            Code::InconsistentMassData => c"inconsistent-mass-data",
            Code::BeyondBox2dRange => c"beyond-box2d-range",
            Code::LossyCapture => c"lossy-capture",
            Code::LossyShape => c"lossy-shape",
            Code::LossyJoint => c"lossy-joint",
            Code::LossyFilter => c"lossy-filter",
            Code::LossyBody => c"lossy-body",
            Code::DialectCannotHold => c"dialect-cannot-hold",
        }
    }

    /// The code with this number, if there is one.
    pub fn from_u32(value: u32) -> Option<Code> {
        Code::ALL.iter().copied().find(|&c| c as u32 == value)
    }
}

impl fmt::Display for Code {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The most warnings a scene keeps; a hostile file could otherwise hold one per element.
/// Past it, one last `warnings-truncated` warning counts the rest.
pub const MAX_WARNINGS: usize = 1000;

/// The most errors a load that goes on past errors records ([`crate::check()`]); the next one
/// ends it, as a markup error does.
pub(crate) const MAX_ERRORS: usize = 100;

/// How bad a diagnostic is.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Severity {
    /// The load succeeded; the scene may not be what the author meant.
    Warning = 1,
    /// The load failed.
    Error = 2,
}

impl Severity {
    /// `"warning"` or `"error"`.
    pub const fn name(self) -> &'static str {
        match self {
            Severity::Warning => "warning",
            Severity::Error => "error",
        }
    }
}

/// Where something is in the input.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Position {
    /// 1-based; 0 when unknown.
    pub line: u32,
    /// 1-based, in characters; 0 when unknown.
    pub column: u32,
    /// Bytes from the start of the input; 0 when unknown.
    pub byte_offset: u64,
}

/// Why a load failed: the code, where, and a message a level designer understands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// What went wrong.
    pub code: Code,
    /// Where in the input; zero when the error has no place in it (an I/O error).
    pub position: Position,
    /// What went wrong, in words, naming the element, value or limit.
    pub message: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let p = self.position;
        write!(f, "{}:{}: error[{}]: {}", p.line, p.column, self.code, self.message)
    }
}

impl std::error::Error for Error {}

impl Error {
    /// The `io` error of a file that cannot be read: its name and the system's reason, as a
    /// load reports one (a host that opens the file itself says it the same way).
    pub fn cannot_read(path: &std::path::Path, e: &std::io::Error) -> Error {
        Error {
            code: Code::Io,
            position: Position::default(),
            message: format!("cannot read {}: {e}", path.display()),
        }
    }
}

/// Where something a load found is: an offset of the decoded text, until it is placed; its
/// position in the file, once it is. An offset becomes a position only through the lines
/// the reader counts (`place::Lines`): while its text is at hand, or once the read is done
/// when the whole text stays in memory (`place::Placer`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Spot {
    Offset(usize),
    Placed(Position),
}

impl Default for Spot {
    fn default() -> Spot {
        Spot::Offset(0)
    }
}

impl Spot {
    /// Offset `at` of the decoded text.
    pub const fn offset(at: usize) -> Spot {
        Spot::Offset(at)
    }

    pub fn placed(position: Position) -> Spot {
        Spot::Placed(position)
    }

    /// Its position, once placed; none (zero) for an offset never placed.
    pub fn position(self) -> Position {
        match self {
            Spot::Offset(_) => Position::default(),
            Spot::Placed(position) => position,
        }
    }

    /// The spot `to` gives an offset (a place in a value's text made a place in the file's),
    /// a position as it is.
    pub fn map_offset(self, to: impl FnOnce(usize) -> usize) -> Spot {
        match self {
            Spot::Offset(at) => Spot::Offset(to(at)),
            placed => placed,
        }
    }

    /// Its offset, while it is not placed.
    pub fn unplaced(self) -> Option<usize> {
        match self {
            Spot::Offset(at) => Some(at),
            Spot::Placed(_) => None,
        }
    }

    /// Where it is in the file, to put spots in order: a load's spots are all placed or all
    /// not, and offsets and byte offsets grow together.
    pub fn order(self) -> u64 {
        match self {
            Spot::Offset(at) => at as u64,
            Spot::Placed(position) => position.byte_offset,
        }
    }
}

/// A coded finding of any load stage, a warning or an error alike: what, and where (see
/// [`Spot`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Finding {
    pub code: Code,
    pub at: Spot,
    pub message: String,
}

/// A [`Finding`] on its way up through `?`, boxed so that a result is no bigger than its
/// value and a pointer.
pub(crate) type Problem = Box<Finding>;

/// The result of a stage that may stop at a [`Problem`].
pub(crate) type Parsed<T> = Result<T, Problem>;

impl Finding {
    /// A finding at offset `at` of the decoded text.
    pub fn new(code: Code, at: usize, message: impl Into<String>) -> Finding {
        Finding::at(code, Spot::Offset(at), message)
    }

    pub fn at(code: Code, at: Spot, message: impl Into<String>) -> Finding {
        Finding { code, at, message: message.into() }
    }

    /// Where it is in the file, to put findings in order (see [`Spot::order`]).
    pub fn order(&self) -> u64 {
        self.at.order()
    }
}

/// A [`Problem`]: the finding that stops a stage; or what a stage's error type makes of
/// one (the reader's, which may also stop at the end of a piece).
#[cold]
pub(crate) fn problem<E: From<Problem>>(code: Code, at: usize, message: impl Into<String>) -> E {
    E::from(Box::new(Finding::new(code, at, message)))
}
