//! Pictures (`box2scene::draw`, `b2s_draw_svg`): what is drawn where, in which style, with
//! which key and labels, for a scene alone and for a simulation's start, end and paths; what
//! a picture holds stays finite and parses as XML whatever the scene.

use box2scene::draw::{Picture, Pose, svg};
use box2scene::{Code, LoadOptions, Scene, Vec2, load};

fn scene(xml: &str) -> Scene {
    load(xml.as_bytes(), &LoadOptions::default()).expect("the scene loads")
}

/// `xml` drawn as `picture` says, parsed.
fn draw(xml: &str, picture: &Picture<'_>) -> Element {
    parse_xml(&svg(&scene(xml), picture).expect("a picture"))
}

fn pose(x: f32, y: f32, angle: f32) -> Pose {
    Pose { position: Vec2 { x, y }, angle }
}

const DRAWN: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<World Version="2">
  <Gravity>0 -10</Gravity>
  <Shapes>
    <Shape Type="Polygon">
      <Name>floor</Name>
      <Vertices><Vertex>-10 0</Vertex><Vertex>10 0</Vertex><Vertex>10 1</Vertex><Vertex>-10 1</Vertex></Vertices>
    </Shape>
    <Shape Type="Circle">
      <Name>wheel</Name>
      <Radius>0.5</Radius>
      <Position>1 0</Position>
    </Shape>
    <Shape Type="Edge">
      <Vertex1>-10 10</Vertex1>
      <Vertex2>-9 10</Vertex2>
    </Shape>
    <Shape Type="Chain">
      <Vertices><Vertex>6 6</Vertex><Vertex>8 6</Vertex><Vertex>7 8</Vertex></Vertices>
      <Loop>true</Loop>
    </Shape>
    <Shape Type="Chain">
      <Vertices><Vertex>-8 2</Vertex><Vertex>-6 3</Vertex></Vertices>
    </Shape>
    <Shape Type="Polygon">
      <Vertices><Vertex>0 0</Vertex><Vertex>2 0</Vertex><Vertex>2 1</Vertex><Vertex>0 1</Vertex></Vertices>
    </Shape>
  </Shapes>
  <Fixtures>
    <Fixture><Shape>0</Shape><Density>1</Density></Fixture>
    <Fixture><Name>rim</Name><Shape>1</Shape><Density>1</Density></Fixture>
    <Fixture><Shape>2</Shape><Density>1</Density></Fixture>
    <Fixture><Shape>3</Shape><Density>1</Density></Fixture>
    <Fixture><Shape>4</Shape><Density>1</Density></Fixture>
    <Fixture><Shape>5</Shape><Density>1</Density></Fixture>
  </Fixtures>
  <Bodies>
    <Body Type="Static">
      <Name>ground</Name>
      <Fixtures><ID>0</ID><ID>2</ID><ID>3</ID><ID>4</ID></Fixtures>
    </Body>
    <Body Type="Dynamic">
      <Name>cart</Name>
      <Position>3 4</Position>
      <Fixtures><ID>1</ID></Fixtures>
    </Body>
    <Body Type="Kinematic">
      <Position>-5 6</Position>
      <Angle>1.5707964</Angle>
      <Fixtures><ID>5</ID></Fixtures>
    </Body>
  </Bodies>
  <Joints>
    <Joint Type="Distance">
      <Name>strut</Name>
      <BodyA>0</BodyA>
      <BodyB>1</BodyB>
      <LocalAnchorA>0 1</LocalAnchorA>
      <LocalAnchorB>1 0</LocalAnchorB>
      <Length>5</Length>
    </Joint>
    <Joint Type="Pulley">
      <BodyA>1</BodyA>
      <BodyB>2</BodyB>
      <GroundAnchorA>3 9</GroundAnchorA>
      <GroundAnchorB>-5 9</GroundAnchorB>
      <LocalAnchorA>0 0</LocalAnchorA>
      <LocalAnchorB>0 0</LocalAnchorB>
      <LengthA>5</LengthA>
      <LengthB>3</LengthB>
    </Joint>
  </Joints>
</World>
"#;

/// An element of a parsed drawing, its text the concatenation of its text children.
#[derive(Debug)]
struct Element {
    name: String,
    attributes: Vec<(String, String)>,
    text: String,
    children: Vec<Element>,
}

impl Element {
    fn attribute(&self, name: &str) -> &str {
        let found = self.attributes.iter().find(|(key, _)| key == name);
        &found.unwrap_or_else(|| panic!("<{}> has no {name}", self.name)).1
    }

    fn number(&self, name: &str) -> f32 {
        self.attribute(name).parse().unwrap_or_else(|_| panic!("{name} is not a number"))
    }

    /// The children other than `<title>`: what is drawn.
    fn drawn(&self) -> Vec<&Element> {
        self.children.iter().filter(|c| c.name != "title").collect()
    }

    fn title(&self) -> &str {
        let title = self.children.iter().find(|c| c.name == "title");
        &title.unwrap_or_else(|| panic!("<{}> has no title", self.name)).text
    }

    /// Every element below this one, depth first.
    fn descendants(&self) -> Vec<&Element> {
        self.children.iter().flat_map(|c| std::iter::once(c).chain(c.descendants())).collect()
    }

    fn count(&self, name: &str) -> usize {
        self.descendants().iter().filter(|e| e.name == name).count()
    }
}

/// The drawing as a tree; panics on anything that is not well-formed XML: an unclosed or
/// mismatched tag, a repeated attribute, an unknown entity, a raw `&` or `<`, text or a
/// second element outside the root.
fn parse_xml(text: &str) -> Element {
    use quick_xml::XmlVersion::Implicit1_0;
    use quick_xml::events::{BytesStart, Event};

    fn element(start: &BytesStart) -> Element {
        let attributes = start.attributes().map(|attribute| {
            let attribute = attribute.expect("a well-formed, unrepeated attribute");
            let value = attribute.normalized_value(Implicit1_0).expect("escaped attribute text");
            (attribute.key.as_ref().to_owned(), value.into_owned())
        });
        Element {
            name: start.name().as_ref().to_owned(),
            attributes: attributes.collect(),
            text: String::new(),
            children: Vec::new(),
        }
    }

    let mut reader = quick_xml::Reader::from_str(text);
    let mut open: Vec<Element> = Vec::new();
    let mut root = None;
    loop {
        let event = reader.read_event();
        let at = reader.buffer_position();
        let finished = match event.unwrap_or_else(|e| panic!("not well-formed at {at}: {e}")) {
            Event::Decl(_) | Event::Comment(_) => None,
            Event::Start(start) => {
                open.push(element(&start));
                None
            }
            Event::Empty(start) => Some(element(&start)),
            Event::End(_) => Some(open.pop().expect("an end tag closes an open element")),
            Event::Text(text) => {
                let text = text.xml10_content();
                match open.last_mut() {
                    Some(parent) => parent.text.push_str(&text),
                    None => assert!(text.trim().is_empty(), "text outside the root at {at}"),
                }
                None
            }
            Event::GeneralRef(reference) => {
                let character = match reference.resolve_char_ref().expect("a valid reference") {
                    Some(c) => c,
                    None => match &*reference {
                        "amp" => '&',
                        "lt" => '<',
                        "gt" => '>',
                        "quot" => '"',
                        "apos" => '\'',
                        other => panic!("unknown entity &{other}; at {at}"),
                    },
                };
                open.last_mut().expect("a reference inside the root").text.push(character);
                None
            }
            Event::Eof => break,
            other => panic!("unexpected {other:?} at {at}"),
        };
        if let Some(done) = finished {
            match open.last_mut() {
                Some(parent) => parent.children.push(done),
                None => assert!(root.replace(done).is_none(), "a second root element at {at}"),
            }
        }
    }
    assert!(open.is_empty(), "unclosed elements: {open:?}");
    root.expect("a root element")
}

/// The `points` of a polygon or polyline, as (x, y) pairs.
fn points(element: &Element) -> Vec<(f32, f32)> {
    let pair = |p: &str| {
        let (x, y) = p.split_once(',').expect("x,y");
        (x.parse().expect("a number"), y.parse().expect("a number"))
    };
    element.attribute("points").split(' ').map(pair).collect()
}

/// The picture's pixels per metre of the world: its width over its view box's.
fn pixels_per_metre(svg: &Element) -> f32 {
    let view: Vec<f32> = svg.attribute("viewBox").split(' ').map(|v| v.parse().unwrap()).collect();
    svg.number("width") / view[2]
}

/// The child of `element` of `class`.
fn class<'e>(element: &'e Element, class: &str) -> &'e Element {
    let found = element
        .children
        .iter()
        .find(|c| c.attributes.iter().any(|(k, v)| k == "class" && v == class));
    found.unwrap_or_else(|| panic!("no {class} in <{}>", element.name))
}

/// The words of the key, in its order.
fn key_texts(svg: &Element) -> Vec<&str> {
    let key = class(svg, "key").children.iter().filter(|c| c.name == "text");
    key.map(|t| t.text.as_str()).collect()
}

fn has_class(element: &Element, class: &str) -> bool {
    element.children.iter().any(|c| c.attributes.iter().any(|(k, v)| k == "class" && v == class))
}

fn close(a: f32, b: f32) -> bool {
    (a - b).abs() <= 1e-4 * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn a_scene_is_drawn_where_its_file_puts_every_body() {
    let svg = draw(DRAWN, &Picture::default());
    assert_eq!(svg.name, "svg");
    assert_eq!(svg.attribute("xmlns"), "http://www.w3.org/2000/svg");
    let [background, key, world, labels] = &svg.children[..] else {
        panic!("a background, the key, the world and the labels: {svg:?}")
    };
    assert_eq!((background.name.as_str(), background.attribute("fill")), ("rect", "white"));
    assert_eq!((key.attribute("class"), labels.attribute("class")), ("key", "labels"));
    assert_eq!(world.attribute("transform"), "scale(1,-1)", "y up");
    let [start] = &world.children[..] else { panic!("one frame: {world:?}") };
    assert_eq!(start.attribute("class"), "start");
    assert!(start.attributes.iter().all(|(k, _)| k != "opacity"), "drawn alone, solid");

    let [ground, cart, turned, joints] = &start.children[..] else {
        panic!("three bodies and the joints: {start:?}")
    };
    assert_eq!(ground.title(), "body 0 \"ground\" (static)");
    let [floor, edge, looped, chain] = &ground.drawn()[..] else { panic!("four shapes") };
    assert_eq!((floor.name.as_str(), floor.title()), ("polygon", "fixture 0, shape 0 \"floor\""));
    assert_eq!(floor.attribute("points"), "-10,0 10,0 10,1 -10,1");
    assert_eq!((edge.name.as_str(), edge.attribute("points")), ("polyline", "-10,10 -9,10"));
    assert_eq!(edge.attribute("fill"), "none");
    assert_eq!(looped.name, "polygon", "a loop is closed");
    assert_eq!((looped.attribute("points"), looped.attribute("fill")), ("6,6 8,6 7,8", "none"));
    assert_eq!((chain.name.as_str(), chain.attribute("points")), ("polyline", "-8,2 -6,3"));

    assert_eq!(cart.title(), "body 1 \"cart\" (dynamic)");
    let [wheel, radius] = &cart.drawn()[..] else { panic!("a circle and its radius") };
    assert_eq!(wheel.title(), "fixture 1 \"rim\", shape 1 \"wheel\"");
    let centre = (wheel.number("cx"), wheel.number("cy"), wheel.number("r"));
    assert_eq!(centre, (4.0, 4.0, 0.5), "(1, 0) on a body at (3, 4)");
    let ends = ["x1", "y1", "x2", "y2"].map(|end| radius.number(end));
    assert_eq!(ends, [4.0, 4.0, 4.5, 4.0], "the radius along the body's x axis");

    assert_eq!(turned.title(), "body 2 (kinematic)");
    let [square] = &turned.drawn()[..] else { panic!("one shape") };
    let expected = [(-5.0, 6.0), (-5.0, 8.0), (-6.0, 8.0), (-6.0, 6.0)];
    for ((x, y), (ex, ey)) in points(square).into_iter().zip(expected) {
        assert!((x - ex).abs() < 1e-6 && (y - ey).abs() < 1e-6, "{square:?}");
    }
    assert_eq!(joints.attribute("class"), "joints");
    assert_eq!(joints.children.len(), 2);

    // Bodies coloured by their type.
    let colours: Vec<(&str, &str, &str)> = [ground, cart, turned]
        .iter()
        .map(|body| (body.attribute("class"), body.attribute("fill"), body.attribute("stroke")))
        .collect();
    assert_eq!(
        colours,
        [
            ("static", "#c8c8c8", "#606060"),
            ("dynamic", "#a8c8f0", "#2a5a9a"),
            ("kinematic", "#b8e0b0", "#3a7a30"),
        ]
    );
    assert_eq!((joints.attribute("fill"), joints.attribute("stroke")), ("#d03030", "#d03030"));
}

/// The world's bounds (x -10..10, y 0..10, the pulley's ground anchors and the edge at the
/// top included) sit 24 px inside the view box, below the key.
#[test]
fn the_view_box_holds_the_world_with_a_margin_and_the_key_above_it() {
    let svg = draw(DRAWN, &Picture { title: "level.xml", ..Picture::default() });
    let view: Vec<f32> = svg.attribute("viewBox").split(' ').map(|v| v.parse().unwrap()).collect();
    let [x, y, width, height] = view[..] else { panic!("four numbers") };
    let ppm = pixels_per_metre(&svg);
    assert!(close(height * ppm, svg.number("height")), "square pixels");
    // A 20 m wide world is drawn 480 px wide at least.
    assert!(close(ppm, (480.0 - 48.0) / 20.0), "{ppm}");
    assert!(close((-10.0 - x) * ppm, 24.0) && close((x + width - 10.0) * ppm, 24.0));
    assert!(close((y + height) * ppm, 24.0), "the margin under y = 0");
    // Above y = 10 (SVG's -10): the margin, the title's row and the key's.
    assert!(close((-10.0 - y) * ppm, 24.0 + 8.0 + 16.0 + 8.0 + 20.0 + 8.0), "{y}");
}

#[test]
fn joints_are_drawn_as_box2d_debug_draw_draws_them() {
    let svg = draw(DRAWN, &Picture::default());
    let joints = &class(&svg, "world").children[0].children[3];
    let [strut, pulley] = &joints.children[..] else { panic!("two joints") };
    assert_eq!(strut.title(), "joint 0 \"strut\" (distance)");
    let [link, a, b] = &strut.drawn()[..] else { panic!("a link and two anchors: {strut:?}") };
    assert_eq!((link.name.as_str(), link.attribute("d")), ("path", "M0,1 4,4"), "anchor to anchor");
    assert_eq!(
        [a.number("cx"), a.number("cy"), b.number("cx"), b.number("cy")],
        [0.0, 1.0, 4.0, 4.0]
    );
    // The cart's wheel (radius 0.5) is the smaller body: a dot a fifth of it.
    assert_eq!((a.number("r"), b.number("r")), (0.1, 0.1));
    assert_eq!(pulley.title(), "joint 1 (pulley)");
    let [rope, _, _] = &pulley.drawn()[..] else { panic!("the rope and two anchors") };
    assert_eq!(rope.attribute("d"), "M3,9 3,4 M-5,9 -5,6 M3,9 -5,9", "through the ground anchors");

    // A revolute joint: from each body's origin to its anchor, lighter, and between them.
    let hinged = DRAWN.replace(r#"<Joint Type="Distance">"#, r#"<Joint Type="Revolute">"#);
    let svg = draw(&hinged, &Picture::default());
    let hinge = &class(&svg, "world").children[0].children[3].children[0];
    let [link, arms, _, _] = &hinge.drawn()[..] else { panic!("link, arms, anchors: {hinge:?}") };
    assert_eq!(link.attribute("d"), "M0,1 4,4");
    assert_eq!(arms.attribute("d"), "M0,0 0,1 M3,4 4,4", "ground and cart origins to anchors");
    assert_eq!(arms.attribute("stroke-opacity"), "0.45");
}

#[test]
fn a_simulation_draws_its_start_faint_its_end_solid_and_the_paths_between() {
    let start = [pose(0.0, 0.0, 0.0), pose(3.0, 4.0, 0.0), pose(-5.0, 6.0, 1.5707964)];
    let end =
        [pose(0.0, 0.0, 0.0), pose(5.0, 4.0, std::f32::consts::PI), pose(-5.0, 6.0, 1.5707964)];
    // Three samples; the cart's second one is lost, so its path breaks there and only the
    // piece of two points after it is drawn; the others never move.
    let nan = f32::NAN;
    let samples = [
        [(0.0, 0.0), (3.0, 4.0), (-5.0, 6.0)],
        [(0.0, 0.0), (nan, nan), (-5.0, 6.0)],
        [(0.0, 0.0), (4.0, 4.0), (-5.0, 6.0)],
        [(0.0, 0.0), (5.0, 4.0), (-5.0, 6.0)],
    ];
    let trajectories: Vec<Vec2> = samples.iter().flatten().map(|&(x, y)| Vec2 { x, y }).collect();
    let picture = Picture {
        start: Some(&start),
        end: Some(&end),
        trajectories: &trajectories,
        ..Picture::default()
    };
    let svg = draw(DRAWN, &picture);
    let world = class(&svg, "world");
    let [faint, paths, solid] = &world.children[..] else { panic!("start, paths, end: {world:?}") };
    assert_eq!((faint.attribute("class"), faint.attribute("opacity")), ("start", "0.3"));
    assert_eq!((solid.attribute("class"), paths.attribute("class")), ("end", "paths"));
    assert_eq!(paths.attribute("stroke"), "#f08a00");
    let drawn: Vec<&str> = paths.children.iter().map(|p| p.attribute("points")).collect();
    assert_eq!(drawn, ["4,4 5,4"]);

    let wheel = |frame: &Element| {
        let cart = &frame.children[1];
        let [circle, radius] = &cart.drawn()[..] else { panic!("a circle and its radius") };
        (circle.number("cx"), circle.number("cy"), radius.number("x2"))
    };
    assert_eq!(wheel(faint), (4.0, 4.0, 4.5));
    // Turned half a turn about (5, 4): the shape at (1, 0) is at (4, 4), its radius to the left.
    let (cx, cy, x2) = wheel(solid);
    assert!(close(cx, 4.0) && close(cy, 4.0) && close(x2, 3.5), "{:?}", wheel(solid));

    let key = key_texts(&svg);
    assert_eq!(
        key,
        [
            "static",
            "kinematic",
            "dynamic",
            "joint",
            "start (faint)",
            "end (solid)",
            "path of a body's origin"
        ]
    );
}

#[test]
fn a_body_without_a_finite_pose_is_not_drawn_nor_are_its_joints() {
    let nan = f32::NAN;
    let start = [pose(0.0, 0.0, 0.0), pose(nan, 4.0, 0.0), pose(-5.0, 6.0, f32::INFINITY)];
    let svg = draw(DRAWN, &Picture { start: Some(&start), ..Picture::default() });
    let frame = &class(&svg, "world").children[0];
    let titles: Vec<&str> = frame.children.iter().map(|c| c.title()).collect();
    assert_eq!(titles, ["body 0 \"ground\" (static)"], "no joint either: each joins the cart");
    let labels: Vec<&str> =
        class(&svg, "labels").children.iter().map(|t| t.text.as_str()).collect();
    assert_eq!(labels, ["ground"]);
}

#[test]
fn a_joint_the_host_did_not_create_is_not_drawn() {
    let picture = Picture { joints: Some(&[false, true]), ..Picture::default() };
    let svg = draw(DRAWN, &picture);
    let joints = &class(&svg, "world").children[0].children[3];
    let titles: Vec<&str> = joints.children.iter().map(|c| c.title()).collect();
    assert_eq!(titles, ["joint 1 (pulley)"]);
    let none = Picture { joints: Some(&[false, false]), ..Picture::default() };
    let svg = draw(DRAWN, &none);
    assert!(!has_class(&class(&svg, "world").children[0], "joints"));
    let key = key_texts(&svg);
    assert_eq!(key, ["static", "kinematic", "dynamic"], "no joint in the key");
}

/// Named bodies are labelled 3 px above their largest shape, centred, or below it, or beside
/// it, where no shape or earlier name is; a name with no such place is left to the tooltip,
/// and the key says so.
#[test]
fn named_bodies_are_labelled_where_a_label_fits() {
    let svg = draw(DRAWN, &Picture::default());
    let ppm = pixels_per_metre(&svg);
    let labels = class(&svg, "labels");
    assert!(close(labels.number("font-size") * ppm, 11.0));
    let [ground, cart] = &labels.children[..] else { panic!("two named bodies: {labels:?}") };
    assert_eq!((ground.text.as_str(), cart.text.as_str()), ("ground", "cart"));
    assert_eq!(ground.number("x"), 0.0);
    // Above its floor (y 0 to 1), not above its bounds, where nothing of it is at x = 0.
    assert!(close(-ground.number("y"), 1.0 + 3.0 / ppm), "above the floor");
    assert_eq!(cart.number("x"), 4.0);
    assert!(close(-cart.number("y"), 4.5 + 3.0 / ppm), "above the wheel");

    // A second body where the cart is, under the same name, finds the place above taken
    // and takes the one below; a third finds both taken.
    let twice = DRAWN.replace(
        "<Position>-5 6</Position>\n      <Angle>1.5707964</Angle>",
        "<Name>cart</Name><Position>3 4</Position>",
    );
    let twice = twice.replace("<Fixtures><ID>5</ID></Fixtures>", "<Fixtures><ID>1</ID></Fixtures>");
    let svg = draw(&twice, &Picture::default());
    let texts: Vec<&str> = class(&svg, "labels").children.iter().map(|t| t.text.as_str()).collect();
    assert_eq!(texts, ["ground", "cart", "cart"], "the second below the wheel");
    let thrice = twice.replace("<Name>ground</Name>", "<Name>cart</Name><Position>3 4</Position>");
    let svg = draw(
        &thrice.replace("<ID>0</ID><ID>2</ID><ID>3</ID><ID>4</ID>", "<ID>1</ID>"),
        &Picture::default(),
    );
    let texts: Vec<&str> = class(&svg, "labels").children.iter().map(|t| t.text.as_str()).collect();
    assert_eq!(texts, ["cart", "cart"], "a third has no place left");
}

/// A static body, its walls and floor around a level: its name goes beside its floor,
/// its largest shape, not above the middle of its bounds, which is the door's top, where it
/// would be read as the door's name.
#[test]
fn a_large_body_is_labelled_beside_its_own_shapes() {
    let polygon = |points: &str| {
        let vertices: String = points.split(';').map(|v| format!("<Vertex>{v}</Vertex>")).collect();
        format!("<Shape Type=\"Polygon\"><Vertices>{vertices}</Vertices></Shape>")
    };
    let xml = format!(
        "<World Version=\"1\"><Shapes>{}{}{}{}</Shapes><Fixtures>{}</Fixtures><Bodies>\
         <Body Type=\"Static\"><Name>Ground</Name><Fixtures><ID>0</ID><ID>1</ID><ID>2</ID>\
         </Fixtures></Body><Body Type=\"Dynamic\"><Name>Door</Name><Fixtures><ID>3</ID>\
         </Fixtures></Body></Bodies><Joints/></World>",
        polygon("-10 0;10 0"),
        polygon("-10 0;-10 5"),
        polygon("10 0;10 5"),
        polygon("-0.5 4;0.5 4;0.5 7;-0.5 7"),
        "<Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture>\
         <Fixture><Shape>2</Shape></Fixture><Fixture><Shape>3</Shape></Fixture>"
    );
    let svg = draw(&xml, &Picture::default());
    let ppm = pixels_per_metre(&svg);
    let [ground, door] = &class(&svg, "labels").children[..] else { panic!("two labels") };
    assert_eq!((ground.text.as_str(), door.text.as_str()), ("Ground", "Door"));
    assert_eq!(ground.number("x"), 0.0);
    assert!(close(-ground.number("y"), 3.0 / ppm), "3 px above the floor at y = 0");
    assert_eq!(door.number("x"), 0.0);
    assert!(close(-door.number("y"), 7.0 + 3.0 / ppm), "above the door");
    assert!(!key_texts(&svg).iter().any(|k| k.contains("tooltips")));
}

/// Two crates stacked on a floor: the lower one's name cannot go above it, on the upper
/// crate, nor below it, on the floor: it goes to its right, centred on it.
#[test]
fn stacked_crates_are_each_labelled_beside_themselves() {
    let square = |y: f32, name: &str| {
        format!(
            "<Body Type=\"Dynamic\"><Name>{name}</Name><Position>0 {y}</Position><Fixtures>\
             <ID>1</ID></Fixtures></Body>"
        )
    };
    let xml = format!(
        "<World Version=\"1\"><Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>-10 -1</Vertex>\
         <Vertex>10 -1</Vertex><Vertex>10 0</Vertex><Vertex>-10 0</Vertex></Vertices></Shape>\
         <Shape Type=\"Polygon\"><Vertices><Vertex>-0.5 0</Vertex><Vertex>0.5 0</Vertex>\
         <Vertex>0.5 1</Vertex><Vertex>-0.5 1</Vertex></Vertices></Shape></Shapes><Fixtures>\
         <Fixture><Shape>0</Shape></Fixture><Fixture><Shape>1</Shape></Fixture></Fixtures>\
         <Bodies><Body Type=\"Static\"><Fixtures><ID>0</ID></Fixtures></Body>{}{}</Bodies>\
         <Joints/></World>",
        square(0.0, "lower"),
        square(1.0, "upper")
    );
    let svg = draw(&xml, &Picture::default());
    let ppm = pixels_per_metre(&svg);
    let [lower, upper] = &class(&svg, "labels").children[..] else { panic!("two labels") };
    assert_eq!((lower.text.as_str(), upper.text.as_str()), ("lower", "upper"));
    // 3 px right of the crate, half of five characters of 7 px further: the label's middle.
    assert!(close(lower.number("x"), 0.5 + (3.0 + 17.5) / ppm), "{}", lower.number("x"));
    // Its box (a quarter of the font under the baseline, the font above) centred on y = 0.5.
    assert!(close(-lower.number("y"), 0.5 - 0.375 * 11.0 / ppm), "{}", lower.number("y"));
    assert_eq!(upper.number("x"), 0.0);
    assert!(close(-upper.number("y"), 2.0 + 3.0 / ppm), "above the upper crate");
}

/// Three bodies in one place under one name: the third finds every place beside the wheel
/// taken, and the key says that a name is only in a tooltip, which every body has.
#[test]
fn the_key_counts_the_names_only_in_tooltips() {
    let svg = draw(DRAWN, &Picture::default());
    assert!(!key_texts(&svg).iter().any(|k| k.contains("tooltips")), "every name shown");
    let three = DRAWN
        .replace(
            "<Position>-5 6</Position>\n      <Angle>1.5707964</Angle>",
            "<Name>cart</Name><Position>3 4</Position>",
        )
        .replace("<Fixtures><ID>5</ID></Fixtures>", "<Fixtures><ID>1</ID></Fixtures>")
        .replace("<Name>ground</Name>", "<Name>cart</Name><Position>3 4</Position>")
        .replace("<ID>0</ID><ID>2</ID><ID>3</ID><ID>4</ID>", "<ID>1</ID>");
    let svg = draw(&three, &Picture::default());
    assert_eq!(class(&svg, "labels").children.len(), 2);
    let key = key_texts(&svg);
    assert_eq!(key.last(), Some(&"1 name only in tooltips"), "{key:?}");
    let titles: Vec<&str> =
        class(&svg, "world").children[0].children[..3].iter().map(|b| b.title()).collect();
    assert_eq!(
        titles,
        ["body 0 \"cart\" (static)", "body 1 \"cart\" (dynamic)", "body 2 \"cart\" (kinematic)"]
    );
}

/// The title, the key and the labels are sized in pixels of the picture: the same for a
/// scene of 2 m and one of 2 km.
#[test]
fn the_key_reads_the_same_whatever_the_scene_s_size() {
    let box_of = |side: f32| {
        format!(
            "<World Version=\"1\"><Shapes><Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex>\
             <Vertex>{side} 0</Vertex><Vertex>{side} {side}</Vertex></Vertices></Shape></Shapes>\
             <Fixtures><Fixture><Shape>0</Shape></Fixture></Fixtures><Bodies><Body Type=\"Static\">\
             <Name>b</Name><Fixtures><ID>0</ID></Fixtures></Body></Bodies><Joints/></World>"
        )
    };
    for side in [2.0, 2000.0] {
        let svg = draw(&box_of(side), &Picture { title: "t", ..Picture::default() });
        let ppm = pixels_per_metre(&svg);
        let key = class(&svg, "key");
        let title = &key.children[0];
        assert_eq!((title.text.as_str(), title.attribute("font-weight")), ("t", "bold"));
        assert!(close(title.number("font-size") * ppm, 16.0), "{side}");
        assert!(close(key.children[2].number("font-size") * ppm, 12.0), "{side}");
        let side_px = svg.number("width").max(svg.number("height"));
        assert!((480.0..=1600.0).contains(&side_px), "{side}: {side_px}");
        assert!(close(class(&svg, "labels").number("font-size") * ppm, 11.0));
    }
}

#[test]
fn titles_and_names_are_escaped_and_the_picture_stays_well_formed() {
    let name = r#"a<b & "c" ]]> </title>"#;
    let xml =
        DRAWN.replace("<Name>cart</Name>", "<Name>a&lt;b &amp; \"c\" ]]&gt; &lt;/title&gt;</Name>");
    let text = svg(&scene(&xml), &Picture { title: name, ..Picture::default() }).unwrap();
    assert!(text.contains("a&lt;b &amp; &quot;c&quot; ]]&gt; &lt;/title&gt;"), "{text}");
    let svg = parse_xml(&text);
    assert_eq!(svg.title(), name, "the document's title");
    assert_eq!(class(&svg, "key").children[0].text, name);
    assert_eq!(
        class(&svg, "world").children[0].children[1].title(),
        format!("body 1 \"{name}\" (dynamic)")
    );
    roxmltree::Document::parse(&text).expect("another parser reads it");
}

#[test]
fn an_empty_scene_draws_a_view_around_the_origin() {
    let svg = draw(
        "<World Version=\"1\"><Shapes/><Fixtures/><Bodies/><Joints/></World>",
        &Picture::default(),
    );
    let view: Vec<f32> = svg.attribute("viewBox").split(' ').map(|v| v.parse().unwrap()).collect();
    let ppm = pixels_per_metre(&svg);
    assert!(close(view[0], -1.0 - 24.0 / ppm) && close(view[2], 2.0 + 48.0 / ppm), "{view:?}");
    assert_eq!(class(&svg, "world").count("title"), 0);
    assert!(class(&svg, "key").children.is_empty(), "nothing to key");
}

/// Two circles at x = +-3e38, at the edges of single precision: every number written is
/// finite in single precision, as viewers read them, and both circles lie inside the view
/// box.
#[test]
fn a_scene_at_the_edges_of_single_precision_is_drawn_in_finite_numbers() {
    let circle = |x: &str| {
        format!(
            "<Body Type=\"Static\"><Name>c</Name><Position>{x} 0</Position><Fixtures><ID>0</ID></Fixtures></Body>"
        )
    };
    let xml = format!(
        "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>1</Radius><Position>0 0</Position></Shape></Shapes>\
         <Fixtures><Fixture><Shape>0</Shape></Fixture></Fixtures><Bodies>{}{}</Bodies><Joints/>\
         </World>",
        circle("3e38"),
        circle("-3e38")
    );
    let paths = [
        Vec2 { x: 3e38, y: 0.0 },
        Vec2 { x: -3e38, y: 0.0 },
        Vec2 { x: -3e38, y: 1.0 },
        Vec2 { x: 3e38, y: 1.0 },
    ];
    let svg = draw(&xml, &Picture { title: "far", trajectories: &paths, ..Picture::default() });
    let finite = |text: &str| -> f32 {
        let value: f32 = text.parse().unwrap_or_else(|_| panic!("{text:?} is not a number"));
        assert!(value.is_finite(), "{text:?} is not finite");
        value
    };
    let view: Vec<f32> = svg.attribute("viewBox").split(' ').map(finite).collect();
    let [x, y, width, height] = view[..] else { panic!("four numbers") };
    assert!(finite(&(x + width).to_string()) > x && y + height > y);
    assert_eq!(finite(svg.attribute("width")), 1600.0);
    assert!(finite(svg.attribute("height")) > 0.0);
    for element in svg.descendants() {
        for (name, value) in &element.attributes {
            if [
                "x",
                "y",
                "cx",
                "cy",
                "r",
                "x1",
                "x2",
                "y1",
                "y2",
                "width",
                "height",
                "font-size",
                "stroke-width",
            ]
            .contains(&name.as_str())
            {
                finite(value);
            }
            if name == "points" {
                value.split([' ', ',']).for_each(|v| _ = finite(v));
            }
        }
    }
    let world = class(&svg, "world");
    let circles: Vec<&Element> =
        world.descendants().into_iter().filter(|e| e.name == "circle").collect();
    let centres: Vec<f32> = circles.iter().map(|c| c.number("cx")).collect();
    assert_eq!(centres.len(), 2);
    for (circle, &cx) in circles.iter().zip(&centres) {
        assert!(x < cx && cx < x + width, "{cx} outside {view:?}");
        assert!(y < -circle.number("cy") && -circle.number("cy") < y + height);
    }
    assert_eq!(centres[0], -centres[1], "the two circles, turned about the origin");
    assert_eq!(class(world, "paths").children.len(), 2);
}

#[test]
fn poses_flags_and_paths_of_the_wrong_length_are_invalid_arguments() {
    let scene = scene(DRAWN);
    let two = [Pose::default(); 2];
    let cases = [
        (Picture { start: Some(&two), ..Picture::default() }, "start holds 2 poses for 3 bodies"),
        (Picture { end: Some(&two), ..Picture::default() }, "end holds 2 poses for 3 bodies"),
        (
            Picture { joints: Some(&[true]), ..Picture::default() },
            "joints holds 1 flags for 2 joints",
        ),
        (
            Picture { trajectories: &[Vec2 { x: 0.0, y: 0.0 }; 4], ..Picture::default() },
            "trajectories hold 4 points, not a multiple of 3",
        ),
    ];
    for (picture, message) in cases {
        let error = svg(&scene, &picture).expect_err(message);
        assert_eq!((error.code, error.message.as_str()), (Code::InvalidArgument, message));
    }
}

/// A circle of 1e-38 m (and one of 1.5 mm), drawn at 2e40 (1.4e5) pixels a metre: written
/// in metres, a viewer would scale every number by that, past single precision, and show
/// nothing. Its numbers are written scaled up by a power of two, to a unit of one or two
/// pixels, normal single-precision numbers in which the circle, the lines, the key and the
/// label keep their sizes in pixels.
#[test]
fn a_tiny_scene_is_written_scaled_up_to_pixels() {
    for radius in ["1e-38", "0.00075"] {
        let xml = format!(
            "<World Version=\"1\"><Shapes><Shape Type=\"Circle\"><Radius>{radius}</Radius>\
             <Position>0 0</Position></Shape></Shapes><Fixtures><Fixture><Shape>0</Shape>\
             </Fixture></Fixtures><Bodies><Body Type=\"Dynamic\"><Name>dot</Name><Fixtures>\
             <ID>0</ID></Fixtures></Body></Bodies><Joints/></World>"
        );
        let svg = draw(&xml, &Picture { title: "tiny", ..Picture::default() });
        let ppm = pixels_per_metre(&svg);
        assert!((1.0..2.0).contains(&ppm), "{radius}: {ppm} pixels a unit");
        let view: Vec<f32> =
            svg.attribute("viewBox").split(' ').map(|v| v.parse().unwrap()).collect();
        for element in svg.descendants() {
            for (name, value) in &element.attributes {
                if ["x", "y", "cx", "cy", "r", "width", "height", "font-size", "stroke-width"]
                    .contains(&name.as_str())
                {
                    let number: f32 = value.parse().expect("a number");
                    assert!(number == 0.0 || number.is_normal(), "{radius}: {name}={value}");
                }
            }
        }
        assert!(view.iter().all(|v| *v == 0.0 || v.is_normal()), "{view:?}");
        let world = class(&svg, "world");
        let circle = world.descendants().into_iter().find(|e| e.name == "circle").unwrap();
        // The circle fills the 480 px picture but for its margins: 216 px of radius.
        assert!(close(circle.number("r") * ppm, 216.0), "{radius}: {}", circle.number("r"));
        assert!(close(world.number("stroke-width") * ppm, 1.5));
        assert!(close(class(&svg, "key").children[0].number("font-size") * ppm, 16.0));
        assert!(close(class(&svg, "labels").number("font-size") * ppm, 11.0));
        assert_eq!(svg.number("width"), 480.0);
    }
}
