//! One case per error and warning code. Each case marks with `⌖` the exact place the
//! diagnostic must point at; the marker is removed before loading, and its line and column
//! (1-based, in characters) are the expected position.

use box2scene::{Code, LoadOptions, load};

const MARK: char = '⌖';

/// The input without its marker, and the marker's line and column.
fn unmark(marked: &str) -> (String, u32, u32) {
    let at = marked.find(MARK).expect("every case marks its position");
    let before = &marked[..at];
    let line = before.matches('\n').count() as u32 + 1;
    let column = before.rsplit('\n').next().unwrap().chars().count() as u32 + 1;
    (marked.replacen(MARK, "", 1), line, column)
}

fn expect_error_with(marked: &str, code: Code, options: &LoadOptions) -> String {
    let (xml, line, column) = unmark(marked);
    let error = load(xml.as_bytes(), options).expect_err("the load must fail");
    assert_eq!(
        (error.code, error.position.line, error.position.column),
        (code, line, column),
        "{}\nin:\n{xml}",
        error.message
    );
    error.message
}

fn expect_error(marked: &str, code: Code) -> String {
    expect_error_with(marked, code, &LoadOptions::default())
}

/// The warnings `xml` loads with: code, line, column and message.
fn warnings_of(xml: &str) -> Vec<(Code, u32, u32, String)> {
    let scene = load(xml.as_bytes(), &LoadOptions::default()).expect("a warning is no failure");
    let found = scene.diagnostics().iter().map(|d| {
        let message = scene.text(d.message).unwrap().to_string();
        (Code::from_u32(d.code).unwrap(), d.line, d.column, message)
    });
    found.collect()
}

fn expect_warning(marked: &str, code: Code) {
    let (xml, line, column) = unmark(marked);
    let found = warnings_of(&xml);
    assert!(
        found.iter().any(|&(c, l, col, _)| (c, l, col) == (code, line, column)),
        "expected {code} at {line}:{column}, found {found:?}"
    );
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    expect_error_with(marked, code, &strict);
}

/// A Version 1 world whose containers hold the given XML.
fn world(shapes: &str, fixtures: &str, bodies: &str, joints: &str) -> String {
    format!(
        "<World Version=\"1\">\n<Shapes>{shapes}</Shapes>\n<Fixtures>{fixtures}</Fixtures>\n\
         <Bodies>{bodies}</Bodies>\n<Joints>{joints}</Joints>\n</World>"
    )
}

const CIRCLE: &str = "<Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape>";
const FIXTURE: &str = "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>";
const TWO_BODIES: &str =
    "<Body Type=\"Static\"/><Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>";

fn joint(kind: &str, fields: &str) -> String {
    world(
        CIRCLE,
        FIXTURE,
        TWO_BODIES,
        &format!("<Joint Type=\"{kind}\"><BodyA>0</BodyA><BodyB>1</BodyB>{fields}</Joint>"),
    )
}

fn polygon(vertices: &[&str]) -> String {
    let vertices: String = vertices.iter().map(|v| format!("<Vertex>{v}</Vertex>")).collect();
    world(&format!("<Shape Type=\"Polygon\"><Vertices>{vertices}</Vertices></Shape>"), "", "", "")
}

#[test]
fn invalid_utf8_points_at_the_first_bad_byte() {
    let error =
        load(b"<World Version=\"1\">\n<Shapes>\xC3\x28</Shapes></World>", &LoadOptions::default())
            .unwrap_err();
    assert_eq!((error.code, error.position.line, error.position.column), (Code::InvalidUtf8, 2, 9));
    assert_eq!(error.position.byte_offset, 28);
}

#[test]
fn nul_byte() {
    let error = load(b"<World>\n  \0</World>", &LoadOptions::default()).unwrap_err();
    assert_eq!((error.code, error.position.line, error.position.column), (Code::NulByte, 2, 3));
}

#[test]
fn unsupported_encoding_declared() {
    expect_error(
        "⌖<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><World Version=\"1\"/>",
        Code::UnsupportedEncoding,
    );
}

#[test]
fn utf16_without_bom_is_named() {
    let bytes: Vec<u8> = "<World/>".encode_utf16().flat_map(u16::to_le_bytes).collect();
    assert_eq!(load(&bytes, &LoadOptions::default()).unwrap_err().code, Code::UnsupportedEncoding);
}

#[test]
fn doctype_forbidden() {
    expect_error(
        "<?xml version=\"1.0\"?>\n⌖<!DOCTYPE World [<!ENTITY a \"aaaa\">]>\n<World Version=\"1\">&a;</World>",
        Code::DoctypeForbidden,
    );
}

#[test]
fn malformed_xml_mismatched_tag() {
    expect_error("<World Version=\"1\">\n<Shapes>⌖</Bodies>\n</World>", Code::MalformedXml);
}

#[test]
fn malformed_xml_unknown_entity() {
    let xml = world(
        &CIRCLE.replace("<Shape ", "<Shape Name=\"a\" ").replace("<Radius>1", "<Radius>⌖&nbsp;1"),
        "",
        "",
        "",
    );
    expect_error(&xml, Code::MalformedXml);
}

#[test]
fn malformed_xml_truncated() {
    expect_error("<World Version=\"1\">\n<Shapes>⌖", Code::MalformedXml);
}

#[test]
fn malformed_xml_second_root() {
    expect_error(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints/></World>\n⌖<World/>",
        Code::MalformedXml,
    );
}

#[test]
fn malformed_xml_empty_file() {
    expect_error("⌖", Code::MalformedXml);
}

#[test]
fn duplicate_attribute() {
    expect_error(
        &world("", "", "<Body Type=\"Static\" ⌖Type=\"Dynamic\"/>", ""),
        Code::DuplicateAttribute,
    );
}

#[test]
fn limit_exceeded_depth() {
    let options = LoadOptions { max_depth: 3, ..LoadOptions::default() };
    let xml = "<World Version=\"1\"><Bodies><Body Type=\"Static\">⌖<UserData><a/></UserData></Body></Bodies></World>";
    let message = expect_error_with(xml, Code::LimitExceeded, &options);
    assert!(message.contains("max_depth"), "{message}");
}

#[test]
fn limit_exceeded_elements() {
    let options = LoadOptions { max_elements: 3, ..LoadOptions::default() };
    let message = expect_error_with(
        "<World Version=\"1\"><Shapes/><Fixtures/>⌖<Bodies/></World>",
        Code::LimitExceeded,
        &options,
    );
    assert!(message.contains("max_elements"), "{message}");
}

#[test]
fn limit_exceeded_text() {
    // Every tag here is shorter than the limit; the name is not.
    let options = LoadOptions { max_text_bytes: 20, ..LoadOptions::default() };
    let xml =
        world("", "", "<Body Type=\"Static\"><Name>⌖a name that is too long</Name></Body>", "");
    expect_error_with(&xml, Code::LimitExceeded, &options);
}

#[test]
fn limit_exceeded_tag() {
    let options = LoadOptions { max_text_bytes: 20, ..LoadOptions::default() };
    let xml = world("", "", "⌖<Body Type=\"Static\"  ><Name>n</Name></Body>", "");
    expect_error_with(&xml, Code::LimitExceeded, &options);
}

#[test]
fn limit_exceeded_comment() {
    let options = LoadOptions { max_text_bytes: 20, ..LoadOptions::default() };
    let xml = world("", "", "⌖<!-- a comment longer than that -->", "");
    expect_error_with(&xml, Code::LimitExceeded, &options);
}

#[test]
fn limit_exceeded_input_size() {
    let options = LoadOptions { max_input_bytes: 10, ..LoadOptions::default() };
    let error = load(world("", "", "", "").as_bytes(), &options).unwrap_err();
    assert_eq!((error.code, error.position.line), (Code::LimitExceeded, 0));
    assert!(error.message.contains("max_input_bytes"));
}

#[test]
fn unexpected_text() {
    expect_error(&world("\n  ⌖junk", "", "", ""), Code::UnexpectedText);
}

#[test]
fn not_a_scene() {
    expect_error("<?xml version=\"1.0\"?>\n⌖<Scene/>", Code::NotAScene);
}

#[test]
fn unsupported_version() {
    let message = expect_error("<World Version=\"⌖7\"/>", Code::UnsupportedVersion);
    assert!(message.contains("1, 2 and 3"), "{message}");
}

#[test]
fn duplicate_container() {
    expect_error(
        "<World Version=\"1\">\n<Shapes/>\n⌖<Shapes/>\n</World>",
        Code::DuplicateContainer,
    );
    expect_error(
        &polygon(&["0 0", "1 0", "1 1"]).replace("</Vertices>", "</Vertices>⌖<Vertices/>"),
        Code::DuplicateContainer,
    );
}

#[test]
fn unexpected_element_in_container() {
    expect_error(&world("⌖<Body Type=\"Static\"/>", "", "", ""), Code::UnexpectedElement);
}

#[test]
fn missing_attribute() {
    expect_error(&world("⌖<Shape><Radius>1</Radius></Shape>", "", "", ""), Code::MissingAttribute);
}

#[test]
fn missing_element() {
    let message = expect_error(
        &world(CIRCLE, "⌖<Fixture><Density>1</Density></Fixture>", "", ""),
        Code::MissingElement,
    );
    assert!(message.contains("Shape"), "{message}");
    expect_error(
        &world("⌖<Shape Type=\"Circle\"><Radius>1</Radius></Shape>", "", "", ""),
        Code::MissingElement,
    );
    expect_error(
        &world(CIRCLE, FIXTURE, TWO_BODIES, "⌖<Joint Type=\"Weld\"><BodyA>0</BodyA></Joint>"),
        Code::MissingElement,
    );
}

#[test]
fn unknown_type() {
    expect_error(&world("<Shape Type=\"⌖Hexagon\"/>", "", "", ""), Code::UnknownType);
    expect_error(&world("", "", "<Body Type=\"⌖Floating\"/>", ""), Code::UnknownType);
}

#[test]
fn unsupported_joint_type() {
    let message = expect_error(&joint("⌖Mouse", ""), Code::UnsupportedJointType);
    assert!(message.contains("mouse"), "{message}");
}

#[test]
fn invalid_int() {
    expect_error(
        &world(
            CIRCLE,
            "<Fixture><Shape>0</Shape><FilterData><GroupIndex>⌖x</GroupIndex></FilterData></Fixture>",
            "",
            "",
        ),
        Code::InvalidInt,
    );
}

#[test]
fn invalid_float() {
    expect_error(
        &world(CIRCLE, "<Fixture><Shape>0</Shape><Density>⌖abc</Density></Fixture>", "", ""),
        Code::InvalidFloat,
    );
}

#[test]
fn float_decimal_comma() {
    let message = expect_error(
        &world(CIRCLE, "<Fixture><Shape>0</Shape><Density> 0⌖,5 </Density></Fixture>", "", ""),
        Code::FloatDecimalComma,
    );
    assert!(message.contains("locale"), "{message}");
}

#[test]
fn non_finite_float() {
    expect_error(
        &world(CIRCLE, "<Fixture><Shape>0</Shape><Friction>⌖NaN</Friction></Fixture>", "", ""),
        Code::NonFiniteFloat,
    );
    expect_error(
        &world(CIRCLE, "<Fixture><Shape>0</Shape><Friction>⌖1e39</Friction></Fixture>", "", ""),
        Code::NonFiniteFloat,
    );
    expect_error(
        &world("", "", "<Body Type=\"Static\"><Position>1 ⌖Infinity</Position></Body>", ""),
        Code::NonFiniteFloat,
    );
}

#[test]
fn invalid_bool() {
    expect_error(
        &world(CIRCLE, "<Fixture><Shape>0</Shape><IsSensor>⌖yes</IsSensor></Fixture>", "", ""),
        Code::InvalidBool,
    );
}

#[test]
fn invalid_vector2() {
    expect_error(
        &world("", "", "<Body Type=\"Static\"><Position>⌖1 2 3</Position></Body>", ""),
        Code::InvalidVector2,
    );
    expect_error(
        &world("", "", "<Body Type=\"Static\"><Position>⌖1,,2</Position></Body>", ""),
        Code::InvalidVector2,
    );
}

#[test]
fn invalid_id() {
    expect_error(&world(CIRCLE, "<Fixture><Shape>⌖-1</Shape></Fixture>", "", ""), Code::InvalidId);
}

#[test]
fn invalid_bits() {
    expect_error(
        &world(
            CIRCLE,
            "<Fixture><Shape>0</Shape><FilterData><MaskBits>⌖-4</MaskBits></FilterData></Fixture>",
            "",
            "",
        ),
        Code::InvalidBits,
    );
}

#[test]
fn out_of_range() {
    expect_error(
        &world(
            CIRCLE,
            "<Fixture><Shape>0</Shape><FilterData><GroupIndex>⌖40000</GroupIndex></FilterData></Fixture>",
            "",
            "",
        ),
        Code::OutOfRange,
    );
}

#[test]
fn id_out_of_range_names_both_sides() {
    let fixtures = FIXTURE.repeat(9);
    let bodies = "<Body Type=\"Static\"/><Body Type=\"Static\"/><Body Type=\"Static\"/>\n<Body Type=\"Static\"><Fixtures><ID>1</ID><ID>⌖12</ID></Fixtures></Body>";
    let message = expect_error(&world(CIRCLE, &fixtures, bodies, ""), Code::IdOutOfRange);
    assert_eq!(message, "body 3 names fixture 12, but the file has 9 fixtures");
}

#[test]
fn id_out_of_range_checked_whatever_the_container_order() {
    let xml = "<World Version=\"1\">\n<Joints><Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>⌖5</BodyB></Joint></Joints>\n<Bodies><Body Type=\"Static\"/><Body Type=\"Static\"/></Bodies><Shapes/><Fixtures/></World>";
    let message = expect_error(xml, Code::IdOutOfRange);
    assert_eq!(message, "joint 0 names body 5 as BodyB, but the file has 2 bodies");
    expect_error(&world("", "<Fixture><Shape>⌖0</Shape></Fixture>", "", ""), Code::IdOutOfRange);
}

#[test]
fn bad_radius() {
    expect_error(
        &world(
            "<Shape Type=\"Circle\"><Radius>⌖0</Radius><Position>0 0</Position></Shape>",
            "",
            "",
            "",
        ),
        Code::BadRadius,
    );
}

#[test]
fn bad_vertex_count() {
    let nine = ["0 0", "1 0", "2 1", "3 2", "3 3", "2 4", "1 4", "0 3", "9 9"];
    let xml = polygon(&nine).replace("<Vertex>9 9", "⌖<Vertex>9 9");
    expect_error(&xml, Code::BadVertexCount);
    expect_error(&polygon(&["1 1"]).replace("<Shape ", "⌖<Shape "), Code::BadVertexCount);
}

#[test]
fn degenerate_polygon() {
    expect_error(
        &polygon(&["0 0", "1 1", "2 2"]).replace("<Shape ", "⌖<Shape "),
        Code::DegeneratePolygon,
    );
    expect_error(
        &polygon(&["0 0", "0.001 0"]).replace("<Shape ", "⌖<Shape "),
        Code::DegeneratePolygon,
    );
    expect_error(
        &polygon(&["0 0", "1 0", "0 0.001", "1 0.0001"]).replace("<Shape ", "⌖<Shape "),
        Code::DegeneratePolygon,
    );
}

#[test]
fn degenerate_edge() {
    let xml = world(
        "⌖<Shape Type=\"Edge\"><Vertex1>1 1</Vertex1><Vertex2>1 1</Vertex2></Shape>",
        "",
        "",
        "",
    )
    .replace("\"1\"", "\"2\"");
    expect_error(&xml, Code::DegenerateEdge);
}

#[test]
fn degenerate_chain() {
    let xml = world("⌖<Shape Type=\"Chain\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>1 0.001</Vertex></Vertices></Shape>", "", "", "").replace("\"1\"", "\"2\"");
    expect_error(&xml, Code::DegenerateChain);
}

#[test]
fn negative_value() {
    expect_error(
        &world(
            CIRCLE,
            "<Fixture><Shape>0</Shape><Restitution>⌖-0.5</Restitution></Fixture>",
            "",
            "",
        ),
        Code::NegativeValue,
    );
    expect_error(
        &world("", "", "<Body Type=\"Dynamic\"><MassData><Mass>⌖-1</Mass></MassData></Body>", ""),
        Code::NegativeValue,
    );
    expect_error(&joint("Distance", "<Length>⌖-2</Length>"), Code::NegativeValue);
}

#[test]
fn joint_self_reference() {
    let xml = world(
        CIRCLE,
        FIXTURE,
        TWO_BODIES,
        "<Joint Type=\"Weld\"><BodyA>1</BodyA><BodyB>⌖1</BodyB></Joint>",
    );
    expect_error(&xml, Code::JointSelfReference);
}

#[test]
fn bad_gear_joint() {
    let revolute = "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>";
    let weld = "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>";
    let gear = |a: &str, b: &str| {
        format!(
            "<Joint Type=\"Gear\"><BodyA>0</BodyA><BodyB>1</BodyB><JointA>{a}</JointA><JointB>{b}</JointB></Joint>"
        )
    };
    let at_weld =
        world(CIRCLE, FIXTURE, TWO_BODIES, &format!("{revolute}{weld}{}", gear("0", "⌖1")));
    assert!(expect_error(&at_weld, Code::BadGearJoint).contains("Weld"));
    let at_itself = world(CIRCLE, FIXTURE, TWO_BODIES, &format!("{revolute}{}", gear("⌖1", "0")));
    assert!(expect_error(&at_itself, Code::BadGearJoint).contains("itself"));
    let at_missing = world(CIRCLE, FIXTURE, TWO_BODIES, &format!("{revolute}{}", gear("0", "⌖7")));
    expect_error(&at_missing, Code::BadGearJoint);
}

#[test]
fn bad_limit() {
    let xml = world(
        CIRCLE,
        FIXTURE,
        TWO_BODIES,
        "⌖<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><EnableLimit>true</EnableLimit><LowerAngle>1</LowerAngle><UpperAngle>-1</UpperAngle></Joint>",
    );
    expect_error(&xml, Code::BadLimit);
    // Without the limit enabled, the same values are fine.
    load(unmark(&xml.replace("true", "false")).0.as_bytes(), &LoadOptions::default()).unwrap();
}

#[test]
fn zero_axis() {
    let xml = world(
        CIRCLE,
        FIXTURE,
        TWO_BODIES,
        "⌖<Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>0 0</LocalAxisA></Joint>",
    );
    expect_error(&xml, Code::ZeroAxis);
}

#[test]
fn bad_ratio() {
    let xml = world(
        CIRCLE,
        FIXTURE,
        TWO_BODIES,
        "⌖<Joint Type=\"Pulley\"><BodyA>0</BodyA><BodyB>1</BodyB><Ratio>0</Ratio></Joint>",
    );
    expect_error(&xml, Code::BadRatio);
}

#[test]
fn io_error() {
    let error =
        box2scene::load_path("/nonexistent/level.xml", &LoadOptions::default()).unwrap_err();
    assert_eq!(error.code, Code::Io);
    assert!(error.message.contains("/nonexistent/level.xml"));
}

#[test]
fn legacy_unversioned() {
    expect_warning(
        "⌖<World><Shapes/><Fixtures/><Bodies/><Joints/></World>",
        Code::LegacyUnversioned,
    );
}

#[test]
fn construct_newer_than_version() {
    expect_warning(
        &world("", "", "<Body Type=\"Static\">⌖<GravityScale>2</GravityScale></Body>", ""),
        Code::ConstructNewerThanVersion,
    );
    expect_warning(&joint("⌖Rope", ""), Code::ConstructNewerThanVersion);
    expect_warning(
        &joint("Weld", "⌖<FrequencyHz>4</FrequencyHz>"),
        Code::ConstructNewerThanVersion,
    );
}

#[test]
fn duplicate_element_last_wins() {
    let xml = world(
        CIRCLE,
        "<Fixture><Shape>0</Shape><Density>1</Density>\n ⌖<Density>2</Density></Fixture>",
        "",
        "",
    );
    expect_warning(&xml, Code::DuplicateElement);
    let scene = load(unmark(&xml).0.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(scene.fixtures()[0].density, 2.0);
}

#[test]
fn unknown_element_and_attribute() {
    expect_warning(
        &world("", "", "<Body Type=\"Static\">⌖<Colour>red<b/></Colour></Body>", ""),
        Code::UnknownElement,
    );
    expect_warning(
        &world("", "", "<Body Type=\"Static\" Colour=\"⌖red\"/>", ""),
        Code::UnknownElement,
    );
    expect_warning(
        &world(
            CIRCLE,
            "<Fixture><Shape>0</Shape></Fixture>",
            "<Body Type=\"Static\"/><Body Type=\"Static\"/>",
            "<Joint Type=\"Weld\"><BodyA>0</BodyA><BodyB>1</BodyB>⌖<LowerAngle>1</LowerAngle></Joint>",
        ),
        Code::UnknownElement,
    );
}

#[test]
fn missing_container() {
    expect_warning(
        "⌖<World Version=\"1\"><Shapes/><Fixtures/><Bodies/></World>",
        Code::MissingContainer,
    );
}

/// The world is checked as it ends, before what follows it is read: in strict mode its
/// missing container is the error, though text after `</World>` is malformed too.
#[test]
fn a_missing_container_is_found_before_what_follows_the_world() {
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    let xml = "⌖<World Version=\"1\"><Shapes/><Fixtures/><Bodies/></World>x";
    expect_error_with(xml, Code::MissingContainer, &strict);
    expect_error(&xml.replace('⌖', "").replace("</World>x", "</World>⌖x"), Code::MalformedXml);
}

/// Farseer's categories are 32-bit flags, its default mask `2147483647` ("all"): all 32 bits
/// are kept, without a word; more than 32 is an error.
#[test]
fn filter_bits_are_kept_whole_up_to_32() {
    let fixture = |category: &str, mask: &str| {
        format!(
            "<Fixture><Shape>0</Shape><FilterData><CategoryBits>{category}</CategoryBits>\
             <MaskBits>{mask}</MaskBits></FilterData></Fixture>"
        )
    };
    let xml = world(CIRCLE, &fixture("0x40000", "2147483647"), "", "");
    let scene = load(xml.as_bytes(), &LoadOptions::default()).unwrap();
    assert!(scene.diagnostics().is_empty());
    let filter = scene.fixtures()[0].filter;
    assert_eq!((filter.category_bits, filter.mask_bits), (0x40000, 0x7FFF_FFFF));
    let xml = world(CIRCLE, &fixture("1", "⌖4294967296"), "", "");
    expect_error(&xml, Code::OutOfRange);
}

/// A decimal comma inside a vector, as every Farseer run on a machine with a comma locale
/// wrote, is named for what it is, at the comma.
#[test]
fn a_decimal_comma_inside_a_vector() {
    for gravity in ["0⌖,5 -20", "0 -9⌖,82"] {
        let xml = format!(
            "<World Version=\"1\"><Gravity>{gravity}</Gravity><Shapes/><Fixtures/><Bodies/><Joints/></World>"
        );
        let message = expect_error(&xml, Code::FloatDecimalComma);
        assert!(message.contains("locale"), "{message}");
    }
}

#[test]
fn polygon_not_convex_ccw() {
    expect_warning(
        &polygon(&["0 0", "0 1", "1 1", "1 0"]).replace("<Shape ", "⌖<Shape "),
        Code::PolygonNotConvexCcw,
    );
}

/// Two dynamic circles, the second at `position`, and one joint between them.
fn pair(position: &str, joint: &str) -> String {
    let bodies = format!(
        "<Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>\
         <Body Type=\"Dynamic\"><Position>{position}</Position><Fixtures><ID>0</ID></Fixtures></Body>"
    );
    world(CIRCLE, FIXTURE, &bodies, joint)
}

fn violation_message(marked: &str) -> String {
    expect_warning(marked, Code::JointStartsViolated);
    let scene = load(unmark(marked).0.as_bytes(), &LoadOptions::default()).unwrap();
    let d = &scene.diagnostics()[0];
    scene.text(d.message).unwrap().to_string()
}

#[test]
fn joint_starts_violated() {
    let hinge = pair("3 4", "<Joint Type=\"Revolute\"><BodyA>⌖0</BodyA><BodyB>1</BodyB></Joint>");
    assert!(violation_message(&hinge).contains("starts 5.000 m from satisfied"));
    let rod = pair(
        "3 0",
        "<Joint Type=\"Distance\"><BodyA>⌖0</BodyA><BodyB>1</BodyB><Length>2.5</Length></Joint>",
    );
    assert!(violation_message(&rod).contains("starts 0.500 m from"));
    let turned = pair(
        "0 0",
        "<Joint Type=\"Weld\"><BodyA>⌖0</BodyA><BodyB>1</BodyB>\
         <ReferenceAngle>0.3</ReferenceAngle></Joint>",
    );
    assert!(violation_message(&turned).contains("starts 0.300 rad from"));
    // Off its axis by 2 m, and 1 m past the upper end of its limit.
    let slider = pair(
        "3 2",
        "<Joint Type=\"Line\"><BodyA>⌖0</BodyA><BodyB>1</BodyB><EnableLimit>true</EnableLimit>\
         <UpperTranslation>2</UpperTranslation></Joint>",
    );
    assert!(violation_message(&slider).contains("starts 2.000 m from"));
}

#[test]
fn satisfied_joints_and_springs_give_no_violation() {
    let satisfied = [
        "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>3 4</LocalAnchorA></Joint>",
        "<Joint Type=\"Distance\"><BodyA>0</BodyA><BodyB>1</BodyB><Length>5</Length></Joint>",
        "<Joint Type=\"Distance\"><BodyA>0</BodyA><BodyB>1</BodyB><FrequencyHz>2</FrequencyHz></Joint>",
        "<Joint Type=\"Prismatic\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>3 4</LocalAxisA></Joint>",
        "<Joint Type=\"Wheel\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAxisA>0.6 0.8</LocalAxisA></Joint>",
        "<Joint Type=\"Rope\"><BodyA>0</BodyA><BodyB>1</BodyB><LocalAnchorA>0 0</LocalAnchorA>\
         <LocalAnchorB>0 0</LocalAnchorB><MaxLength>6</MaxLength></Joint>",
        "<Joint Type=\"Friction\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
        "<Joint Type=\"Motor\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>",
    ];
    for joint in satisfied {
        let xml = pair("3 4", joint).replace("Version=\"1\"", "Version=\"2\"");
        let scene = load(xml.as_bytes(), &LoadOptions::default()).unwrap();
        assert!(scene.diagnostics().is_empty(), "{joint}");
    }
}

#[test]
fn dynamic_body_zero_density() {
    let xml = world(
        CIRCLE,
        "<Fixture><Shape>0</Shape></Fixture>",
        "⌖<Body Type=\"Dynamic\"><Fixtures><ID>0</ID></Fixtures></Body>",
        "",
    );
    expect_warning(&xml, Code::DynamicBodyZeroDensity);
    let with_mass =
        unmark(&xml.replace("\"Dynamic\">", "\"Dynamic\"><MassData><Mass>2</Mass></MassData>")).0;
    assert!(load(with_mass.as_bytes(), &LoadOptions::default()).unwrap().diagnostics().is_empty());
}

#[test]
fn positions_count_characters_after_a_bom_and_in_utf16() {
    let xml = "<World Version=\"1\">\n<Bodies><Body Type=\"Static\"><Name>é</Name><Angle>x</Angle></Body></Bodies></World>";
    let column = "<Bodies><Body Type=\"Static\"><Name>é</Name><Angle>".chars().count() as u32 + 1;
    let mut bytes = b"\xEF\xBB\xBF".to_vec();
    bytes.extend_from_slice(xml.as_bytes());
    let error = load(&bytes, &LoadOptions::default()).unwrap_err();
    assert_eq!(
        (error.code, error.position.line, error.position.column),
        (Code::InvalidFloat, 2, column)
    );
    assert_eq!(error.position.byte_offset, 3 + xml.find(">x<").unwrap() as u64 + 1);

    let mut utf16 = vec![0xFF, 0xFE];
    utf16.extend(xml.encode_utf16().flat_map(u16::to_le_bytes));
    let error = load(&utf16, &LoadOptions::default()).unwrap_err();
    assert_eq!(
        (error.code, error.position.line, error.position.column),
        (Code::InvalidFloat, 2, column)
    );
    assert_eq!(
        error.position.byte_offset,
        2 + 2 * xml[..xml.find(">x<").unwrap() + 1].encode_utf16().count() as u64
    );
}

#[test]
fn every_code_has_a_distinct_kebab_name() {
    let names: std::collections::HashSet<_> = Code::ALL.iter().map(|c| c.name()).collect();
    assert_eq!(names.len(), Code::ALL.len());
    assert!(
        names
            .iter()
            .all(|n| n.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-'))
    );
    for &code in Code::ALL {
        assert_eq!(Code::from_u32(code as u32), Some(code));
    }
}

/// A Version 3 (Farseer layout) world.
fn world_v3(shapes: &str, fixtures: &str, bodies: &str) -> String {
    format!(
        "<World Version=\"3\">\n<Shapes>{shapes}</Shapes>\n<Fixtures>{fixtures}</Fixtures>\n\
         <Bodies>{bodies}</Bodies>\n<Joints/>\n</World>"
    )
}

const V3_CIRCLE: &str =
    "<Shape Type=\"Circle\" Density=\"2\"><Radius>1</Radius><Position>0 0</Position></Shape>";

#[test]
fn farseer_only_joint() {
    let message_of = |xml: &str| {
        let scene = load(unmark(xml).0.as_bytes(), &LoadOptions::default()).unwrap();
        (scene.joints()[0].kind(), scene.text(scene.diagnostics()[0].message).unwrap().to_owned())
    };
    let xml = joint("⌖Angle", "<BiasFactor>0.2</BiasFactor><TargetAngle>1</TargetAngle>")
        .replace("\"1\"", "\"2\"");
    expect_warning(&xml, Code::FarseerOnlyJoint);
    assert_eq!(message_of(&xml).0, Some(box2scene::JointKind::Unsupported));
    let slider = joint("⌖Slider", "<MinLength>1</MinLength><MaxLength>2</MaxLength>")
        .replace("\"1\"", "\"2\"");
    expect_warning(&slider, Code::FarseerOnlyJoint);
}

#[test]
fn line_joint_is_wheel() {
    let xml = joint("Line", "<FrequencyHz>4</FrequencyHz><LocalXAxis>0 1</LocalXAxis>")
        .replace("<Joint ", "⌖<Joint ")
        .replace("\"1\"", "\"2\"");
    expect_warning(&xml, Code::LineJointIsWheel);
    let scene = load(unmark(&xml).0.as_bytes(), &LoadOptions::default()).unwrap();
    let wheel = &scene.joints()[0];
    assert_eq!(wheel.kind(), Some(box2scene::JointKind::Wheel));
    assert_eq!(
        (wheel.frequency_hz, wheel.damping_ratio),
        (4.0, 0.7),
        "the wheel's default damping fills in"
    );
    assert_eq!(wheel.local_axis_a, box2scene::Vec2::new(0.0, 1.0));
}

/// Farseer wrote a process-wide counter into a fixture's `Id` and bound Pairs by
/// position: Ids repeat, go missing and differ from positions, silently.
#[test]
fn farseer_ids_are_informational() {
    let xml = world_v3(
        V3_CIRCLE,
        "<Fixture Id=\"17\"><Friction>0.5</Friction></Fixture><Fixture Id=\"17\"/><Fixture/>",
        "<Body Type=\"Static\" Id=\"3\"><Bindings><Pair FixtureId=\"0\" ShapeId=\"0\"/>\
         <Pair FixtureId=\"2\" ShapeId=\"0\"/></Bindings></Body>",
    );
    let scene = load(xml.as_bytes(), &LoadOptions::default()).unwrap();
    assert!(scene.diagnostics().is_empty());
    let friction: Vec<_> = scene.fixtures().iter().map(|f| f.friction).collect();
    assert_eq!(friction, [0.5, 0.2]);
    let v2 = "<World Version=\"2\"><Shapes>SHAPE</Shapes><Fixtures><Fixture Id=\"9\">\
              <Shape>0</Shape></Fixture></Fixtures><Bodies><Body Type=\"Static\" Id=\"4\">\
              <Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints/></World>"
        .replace("SHAPE", CIRCLE);
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    assert!(load(v2.as_bytes(), &strict).unwrap().diagnostics().is_empty());
}

#[test]
fn farseer_v3_pairs_are_checked() {
    // The fixture's Id is 5, but a Pair names positions: there is only position 0.
    let past_the_end = world_v3(
        V3_CIRCLE,
        "<Fixture Id=\"5\"/>",
        "<Body Type=\"Static\"><Bindings><Pair FixtureId=\"0\" ShapeId=\"0\"/>\
         <Pair FixtureId=\"⌖5\" ShapeId=\"0\"/></Bindings></Body>",
    );
    let message = expect_error(&past_the_end, Code::IdOutOfRange);
    assert_eq!(
        message,
        "body 0 binds fixture 5 (a position in <Fixtures>, counted from 0), but the file has 1 fixture"
    );
    let unknown_shape = world_v3(
        V3_CIRCLE,
        "<Fixture Id=\"4\"/>",
        "<Body Type=\"Static\"><Bindings><Pair FixtureId=\"0\" ShapeId=\"⌖1\"/></Bindings></Body>",
    );
    expect_error(&unknown_shape, Code::IdOutOfRange);
    let no_shape = world_v3(
        V3_CIRCLE,
        "<Fixture Id=\"4\"/>",
        "<Body Type=\"Static\"><Bindings>⌖<Pair FixtureId=\"0\"/></Bindings></Body>",
    );
    expect_error(&no_shape, Code::MissingAttribute);
    let negative = world_v3(
        "<Shape Type=\"Circle\" Density=\"⌖-2\"><Radius>1</Radius><Position>0 0</Position></Shape>",
        "",
        "",
    );
    expect_error(&negative, Code::NegativeValue);
}

/// `<Tag>` is Aether.Physics2D's UserData in Version 3, and unknown before.
#[test]
fn tag_is_user_data_only_in_version_3() {
    let tag = "<Tag><Type>System.String</Type><Value><string>x</string></Value></Tag>";
    let v1 = world(CIRCLE, &FIXTURE.replace("<Density>", &format!("⌖{tag}<Density>")), "", "");
    expect_warning(&v1, Code::UnknownElement);
}

#[test]
fn layouts_do_not_mix() {
    let fixtures_in_v3 = world_v3(
        V3_CIRCLE,
        "<Fixture Id=\"0\"/>",
        "<Body Type=\"Static\">⌖<Fixtures><ID>0</ID></Fixtures></Body>",
    );
    expect_error(&fixtures_in_v3, Code::UnexpectedElement);
    let bindings_in_v1 = world(CIRCLE, FIXTURE, "<Body Type=\"Static\">⌖<Bindings/></Body>", "");
    expect_error(&bindings_in_v1, Code::UnexpectedElement);
    expect_warning(
        &world(CIRCLE, "<Fixture Id=\"⌖0\"><Shape>0</Shape></Fixture>", "", ""),
        Code::UnknownElement,
    );
}

/// Loads `xml` from a file of its own, with the default options.
fn load_from_a_file(xml: &[u8]) -> Result<box2scene::Scene, box2scene::Error> {
    static FILES: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = FILES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file = std::env::temp_dir().join(format!("box2scene-diag-{}-{n}.xml", std::process::id()));
    std::fs::write(&file, xml).unwrap();
    let scene = box2scene::load_path(&file, &LoadOptions::default());
    std::fs::remove_file(&file).unwrap();
    scene
}

/// `xml` fails with `code` at `line` and `column`, loaded from memory and from a file.
fn expect_error_in_both(xml: &[u8], code: Code, line: u32, column: u32) {
    for (from, loaded) in
        [("memory", load(xml, &LoadOptions::default())), ("a file", load_from_a_file(xml))]
    {
        let error = loaded.expect_err("the load must fail");
        assert_eq!(
            (error.code, error.position.line, error.position.column),
            (code, line, column),
            "from {from}: {}\nin:\n{}",
            error.message,
            String::from_utf8_lossy(xml)
        );
    }
}

/// [`expect_error_in_both`] at the marker of `marked`.
fn expect_marked_error_in_both(marked: &str, code: Code) {
    let (xml, line, column) = unmark(marked);
    expect_error_in_both(xml.as_bytes(), code, line, column);
}

/// A fixture whose `<Density>` holds `value`.
fn density(value: &str) -> String {
    world(CIRCLE, &format!("<Fixture><Shape>0</Shape><Density>{value}</Density></Fixture>"), "", "")
}

/// A circle whose `<Position>` holds `value`.
fn position(value: &str) -> String {
    world(
        &format!("<Shape Type=\"Circle\"><Radius>1</Radius><Position>{value}</Position></Shape>"),
        "",
        "",
        "",
    )
}

/// An offset in a value's text, after references that are longer written than read, is
/// where it is written (it was added to the value's start as if they were one byte).
#[test]
fn a_position_after_references_in_a_value_is_where_it_is_written() {
    expect_marked_error_in_both(&position("&#49;&#49;&#49;, ⌖x"), Code::InvalidFloat);
    expect_marked_error_in_both(&position("&#x31; ⌖&amp;x"), Code::InvalidFloat);
    expect_marked_error_in_both(&position("&#x20;&#49;, ⌖x"), Code::InvalidFloat);
    expect_marked_error_in_both(&density("&#32; ⌖-1"), Code::NegativeValue);
}

/// Lines end at CR LF, as an editor counts them: a value holding them is not a line early.
#[test]
fn a_position_after_crlf_in_a_value_is_on_its_line() {
    let xml = position("\r\n  1,\r\n  ⌖x\r\n").replace('\n', "\r\n").replace("\r\r\n", "\r\n");
    expect_marked_error_in_both(&xml, Code::InvalidFloat);
    expect_marked_error_in_both(&density("\r\n ⌖-1"), Code::NegativeValue);
}

/// A CR LF cut by the end of a 64 KiB piece of the file is one line end all the same.
#[test]
fn a_crlf_across_a_piece_of_the_file_is_one_line_end() {
    // 27 bytes before the first CR LF: the one at 65535 is cut.
    let xml =
        format!("<World Version=\"1\"><Shapes>{}<Shape Type=\"Nope\"/>", "\r\n".repeat(40_000));
    expect_error_in_both(xml.as_bytes(), Code::UnknownType, 40_001, 14);
}

/// A lone CR (old Mac line ends) ends a line too.
#[test]
fn a_lone_cr_starts_a_line() {
    let xml = position("\r  1,\r  x").replace('\n', "\r");
    // The world's own line ends come before: <World>, <Shapes>..., so the value is on line 2.
    expect_error_in_both(xml.as_bytes(), Code::InvalidFloat, 4, 3);
    let unexpected = "<World Version=\"1\">\r<Shapes>\r\r  oops</Shapes></World>";
    expect_error_in_both(unexpected.as_bytes(), Code::UnexpectedText, 4, 3);
}

/// A comment or CDATA inside a value splits it; what follows is where it is written.
#[test]
fn a_position_after_a_comment_or_cdata_in_a_value_is_where_it_is_written() {
    expect_marked_error_in_both(&position("1 <!-- one -->, ⌖x"), Code::InvalidFloat);
    expect_marked_error_in_both(&position("<![CDATA[1]]>, ⌖x"), Code::InvalidFloat);
    expect_marked_error_in_both(&position("&#49;<!--c--><![CDATA[ ]]>&#44;⌖x"), Code::InvalidFloat);
    expect_marked_error_in_both(&density("<!-- c -->\n  ⌖-1"), Code::NegativeValue);
}

/// Text where only elements may be, after a reference, is where it is written.
#[test]
fn unexpected_text_after_a_reference_is_where_it_is_written() {
    let xml = "<World Version=\"1\"><Shapes>&#32;&#x20;\n ⌖oops</Shapes></World>";
    expect_marked_error_in_both(xml, Code::UnexpectedText);
}

/// The same in an attribute's value, whose references are resolved and white space
/// normalised.
#[test]
fn a_position_after_references_in_an_attribute_is_where_it_is_written() {
    let shape = "<Shape Type=\"Circle\" Density=\"&#32;&#x20;\r\n⌖x\"><Radius>1</Radius>\
                 <Position>0 0</Position></Shape>";
    expect_marked_error_in_both(&world_v3(shape, "", ""), Code::InvalidFloat);
    let pair = "<Body Type=\"Static\"><Bindings><Pair FixtureId=\"&#48;\" ShapeId=\"&#9;⌖-1\"/>\
                </Bindings></Body>";
    expect_marked_error_in_both(&world_v3(V3_CIRCLE, "<Fixture/>", pair), Code::InvalidId);
}

/// A `<Centroid>` belongs to polygons only: elsewhere it is warned about, and ignored.
#[test]
fn a_centroid_on_a_circle_or_edge_is_ignored() {
    let circle =
        world(&CIRCLE.replace("</Shape>", "⌖<Centroid>1 2</Centroid></Shape>"), "", "", "");
    expect_warning(&circle, Code::UnknownElement);
    let edge = world(
        "<Shape Type=\"Edge\">⌖<Centroid>1 2</Centroid><Vertex1>0 0</Vertex1><Vertex2>1 0</Vertex2>\
         </Shape>",
        "",
        "",
        "",
    )
    .replace("\"1\"", "\"2\"");
    expect_warning(&edge, Code::UnknownElement);
    for xml in [circle, edge] {
        let scene = load(unmark(&xml).0.as_bytes(), &LoadOptions::default()).unwrap();
        assert!(!scene.shapes()[0].centroid_given, "{xml}");
    }
}

/// A Version 3 fixture is a template: its body's Pairs give it its shape and the shape's
/// Density; a `<Shape>` or `<Density>` of its own is warned about, not dropped silently.
#[test]
fn a_version_3_fixtures_own_shape_and_density_are_warned_about() {
    let pair =
        "<Body Type=\"Dynamic\"><Bindings><Pair FixtureId=\"0\" ShapeId=\"0\"/></Bindings></Body>";
    let density = world_v3(V3_CIRCLE, "<Fixture Id=\"0\">⌖<Density>7</Density></Fixture>", pair);
    expect_warning(&density, Code::UnknownElement);
    let shape = world_v3(V3_CIRCLE, "<Fixture Id=\"0\">⌖<Shape>0</Shape></Fixture>", pair);
    expect_warning(&shape, Code::UnknownElement);
    let scene = load(unmark(&density).0.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(scene.fixtures()[0].density, 2.0, "the shape's Density attribute wins");
    let box2scene = box2scene::WriteOptions {
        dialect: box2scene::Dialect::Box2scene as u32,
        ..Default::default()
    };
    let written = box2scene::write(&scene, &box2scene).unwrap();
    assert_eq!(written.matches("<Density>").count(), 1, "{written}");
    let again = load(written.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(again.fixtures()[0].density, 2.0);
}

/// A shape named both by its `Name` attribute and by a `<Name>` element: the element wins,
/// and the attribute's name is not lost without a word.
#[test]
fn a_shape_named_twice_is_warned_about() {
    let shape = "<Shape Type=\"Circle\" Name=\"attribute\"><Radius>1</Radius>⌖<Name>element</Name>\
                 <Position>0 0</Position></Shape>";
    let xml = world(shape, "", "", "");
    expect_warning(&xml, Code::DuplicateElement);
    let scene = load(unmark(&xml).0.as_bytes(), &LoadOptions::default()).unwrap();
    assert_eq!(scene.find_shape("element"), Some(0));
    assert_eq!(scene.find_shape("attribute"), None);
    let one = world(&CIRCLE.replace("<Shape ", "<Shape Name=\"only\" "), "", "", "");
    let scene = load(one.as_bytes(), &LoadOptions::default()).unwrap();
    assert!(scene.diagnostics().is_empty(), "a Name attribute alone is fine");
    assert_eq!(scene.find_shape("only"), Some(0));
}

/// The message of the one warning `marked` gives at its marker, with `code`.
fn warning_message(marked: &str, code: Code) -> String {
    let (xml, line, column) = unmark(marked);
    let found = warnings_of(&xml);
    match found.as_slice() {
        [(c, l, col, message)] if (*c, *l, *col) == (code, line, column) => message.clone(),
        _ => panic!("expected one {code} at {line}:{column}, found {found:?}"),
    }
}

/// A misspelt element or attribute is named with the nearest name its object knows, in the
/// format's spelling; a name far from every known one gets no hint.
#[test]
fn an_unknown_name_near_a_known_one_gets_a_hint() {
    let fixture = world(CIRCLE, "<Fixture><Shape>0</Shape>⌖<Densty>1</Densty></Fixture>", "", "");
    let message = warning_message(&fixture, Code::UnknownElement);
    assert_eq!(message, "unknown element <Densty> in <Fixture> ignored (did you mean <Density>?)");
    // Two letters swapped are one edit; case does not count.
    let body = world("", "", "<Body Type=\"Static\">⌖<POSITOIN>1 2</POSITOIN></Body>", "");
    let message = warning_message(&body, Code::UnknownElement);
    assert_eq!(message, "unknown element <POSITOIN> in <Body> ignored (did you mean <Position>?)");
    let joint = joint("Revolute", "⌖<EnableLimt>true</EnableLimt>");
    let message = warning_message(&joint, Code::UnknownElement);
    assert!(message.ends_with("(did you mean <EnableLimit>?)"), "{message}");
    let attribute =
        "<World Version=\"1\" Verison=\"⌖2\"><Shapes/><Fixtures/><Bodies/><Joints/></World>";
    let message = warning_message(attribute, Code::UnknownElement);
    assert_eq!(message, "unknown attribute Verison on <World> ignored (did you mean Version?)");
    for far in ["<Wind/>", "<D/>", "<Dens/>", "<DensityOfTheMaterialUsedHere/>"] {
        let fixture = world(CIRCLE, &format!("<Fixture><Shape>0</Shape>⌖{far}</Fixture>"), "", "");
        let message = warning_message(&fixture, Code::UnknownElement);
        assert!(!message.contains("did you mean"), "{far}: {message}");
    }
}

/// A revolute limit or a body angle written in degrees where radians are meant (a whole
/// number beyond a full turn, within one in degrees) is a warning of its own at the value,
/// which says what it would be in radians; nothing else is.
#[test]
fn angle_in_degrees() {
    let door = joint(
        "Revolute",
        "<EnableLimit>true</EnableLimit><LowerAngle>⌖-45</LowerAngle><UpperAngle>0.5</UpperAngle>",
    );
    assert_eq!(
        warning_message(&door, Code::AngleInDegrees),
        "<LowerAngle> is -45, a whole number beyond a full turn: it is read as radians; \
         as degrees it would be -0.7853982 rad"
    );
    let upper = joint("Revolute", "<UpperAngle>⌖360</UpperAngle>");
    expect_warning(&upper, Code::AngleInDegrees);
    let body = world("", "", "<Body Type=\"Static\"><Angle>⌖90</Angle></Body>", "");
    expect_warning(&body, Code::AngleInDegrees);
    let radians = [
        "<Angle>6</Angle>",
        "<Angle>-6.2</Angle>",
        "<Angle>12.5</Angle>",
        "<Angle>720</Angle>",
        "<Angle>3.4028235E+38</Angle>",
    ];
    for angle in radians {
        let xml = world("", "", &format!("<Body Type=\"Static\">{angle}</Body>"), "");
        assert_eq!(warnings_of(&xml), [], "{angle}");
    }
    let slider = joint("Prismatic", "<LowerTranslation>-45</LowerTranslation>");
    assert_eq!(warnings_of(&slider), []);
}

/// A misspelt `Type` of a shape, body or joint is named with the nearest the format has, as
/// a misspelt element is; one far from every kind gets no hint.
#[test]
fn an_unknown_type_near_a_known_one_gets_a_hint() {
    let message = expect_error(&world("<Shape Type=\"⌖Polgon\"/>", "", "", ""), Code::UnknownType);
    assert_eq!(
        message,
        "unknown shape Type \"Polgon\" (did you mean Polygon?): expected Circle, Polygon, Edge or Chain"
    );
    let message = expect_error(&world("", "", "<Body Type=\"⌖dynamc\"/>", ""), Code::UnknownType);
    assert_eq!(
        message,
        "unknown body Type \"dynamc\" (did you mean Dynamic?): expected Static, Dynamic or Kinematic"
    );
    let message = expect_error(&joint("⌖Revolut", ""), Code::UnsupportedJointType);
    assert!(
        message.starts_with("unknown joint Type \"Revolut\" (did you mean Revolute?); "),
        "{message}"
    );
    let message = expect_error(&joint("⌖Wheeel", ""), Code::UnsupportedJointType);
    assert!(message.contains("(did you mean Wheel?)"), "{message}");
    let message = expect_error(&world("<Shape Type=\"⌖Hexagon\"/>", "", "", ""), Code::UnknownType);
    assert!(!message.contains("did you mean"), "{message}");
    let message = expect_error(&joint("⌖Mouse", ""), Code::UnsupportedJointType);
    assert!(!message.contains("did you mean"), "{message}");
}

/// Warnings past the limit are counted and not kept, wherever they are found: here 990 in
/// the reader (unknown elements) and 20 in the check made once the scene is read (joints
/// that start far from satisfied). The kept ones keep their words, and the count points at
/// the first warning not kept, in the check's part.
#[test]
fn warnings_past_the_limit_from_the_reader_and_the_check() {
    let hinges: String = (0..20)
        .map(|_| "<Joint Type=\"Revolute\"><BodyA>0</BodyA><BodyB>1</BodyB></Joint>\n")
        .collect();
    let xml =
        pair("3 4", &hinges).replace("<Shapes>", &format!("{}<Shapes>", "<Shap/>\n".repeat(990)));
    let found = warnings_of(&xml);
    assert_eq!(found.len(), 1001);
    assert_eq!(
        found[0],
        (
            Code::UnknownElement,
            2,
            1,
            "unknown element <Shap> in <World> ignored (did you mean <Shapes>?)".to_string()
        )
    );
    let last_kept = "joint 9 starts 5.000 m from satisfied where the file places bodies 0 and \
                     1; an engine pulls them together in its first steps";
    assert_eq!(found[999], (Code::JointStartsViolated, 1004, 31, last_kept.to_string()));
    let not_kept = "10 more warnings from here on were not kept (a scene keeps 1000)";
    assert_eq!(found[1000], (Code::WarningsTruncated, 1005, 31, not_kept.to_string()));
    let strict = LoadOptions { strict: true, ..LoadOptions::default() };
    let error = load(xml.as_bytes(), &strict).expect_err("strict");
    assert_eq!(
        (error.code, error.position.line, error.position.column),
        (Code::UnknownElement, 2, 1)
    );
    assert_eq!(
        error.message,
        "unknown element <Shap> in <World> ignored (did you mean <Shapes>?) (strict mode)"
    );
}
