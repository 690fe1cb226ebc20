//! A deterministic generator of Box2Scene files with every shape, joint and field drawn at
//! random, odd floats and odd names included, and what two scenes must share to be the
//! same: shared by the writer's and the builder's tests.

use std::fmt::Write as _;

use box2scene::{Body, Fixture, Joint, Scene, Shape, Str};

/// Everything a scene holds, bit for bit (the dump's floats are shortest round-trip text),
/// except what describes the file rather than the scene: its version and its warnings.
/// The records follow the dump as C reads them (pool ranges and user data indices as they
/// are), but for their names, whose pointers differ from scene to scene.
pub fn content(scene: &Scene) -> String {
    let json = scene.to_json();
    let body = json.split_once("\n  \"gravity\"").unwrap().1;
    let mut content = body.split_once("\n  \"diagnostics\"").unwrap().0.to_string();
    let name = Str::NULL;
    for s in scene.shapes() {
        writeln!(content, "{:?}", Shape { name, ..*s }).unwrap();
    }
    for f in scene.fixtures() {
        writeln!(content, "{:?}", Fixture { name, ..*f }).unwrap();
    }
    for b in scene.bodies() {
        writeln!(content, "{:?}", Body { name, ..*b }).unwrap();
    }
    for j in scene.joints() {
        writeln!(content, "{:?}", Joint { name, ..*j }).unwrap();
    }
    content
}

/// A small deterministic generator (SplitMix64).
pub struct Random(pub u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    pub fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }

    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }

    /// Any finite float, odd ones often.
    pub fn float(&mut self) -> f32 {
        let odd = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f32::MAX,
            -f32::MAX,
            f32::MIN_POSITIVE,
            f32::from_bits(1),
            -f32::from_bits(0x007F_FFFF),
            0.1,
            1e-5,
            9.999999e-6,
            1e16,
            8.369571e-36,
        ];
        if self.chance(40) {
            return self.pick(&odd);
        }
        loop {
            let value = f32::from_bits(self.next() as u32);
            if value.is_finite() {
                return value;
            }
        }
    }

    /// A float that is not negative (negative zero passes the loader's check).
    pub fn non_negative(&mut self) -> f32 {
        let value = self.float();
        if value.is_sign_negative() && value != 0.0 { -value } else { value }
    }

    /// A float of an ordinary size, for geometry that Box2D's checks must accept.
    pub fn ordinary(&mut self, scale: f32) -> f32 {
        (self.below(2001) as f32 - 1000.0) / 1000.0 * scale
    }
}

/// Shortest round-trip text, in either of the spellings the format allows.
fn num(value: f32) -> String {
    format!("{value:e}")
}

fn vec2(x: f32, y: f32) -> String {
    format!("{} {}", num(x), num(y))
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('\r', "&#13;")
}

const NAMES: &[&str] = &[
    "",
    "ground",
    "a & b",
    "<tag>",
    "say \"hi\" 'there'",
    "tab\tinside",
    "é€ 😀 日本",
    "line\r\nbreak",
    "]]>",
];
const USER_DATA: &[&str] = &[
    "<Type>System.String</Type><Value><string>ok &amp; fine</string></Value>",
    "plain text",
    "",
    "\n  <a x=\"1\">nested <b/> text</a>\n",
    "<Type>System.Int32</Type><Value><int>42</int></Value><Extra/>",
];

fn element(out: &mut String, name: &str, text: &str) {
    let _ = write!(out, "<{name}>{text}</{name}>");
}

fn named(out: &mut String, r: &mut Random) {
    if r.chance(50) {
        element(out, "Name", &escape(r.pick(NAMES)));
    }
    if r.chance(20) {
        element(out, "UserData", r.pick(USER_DATA));
    }
}

/// A scene with every shape, joint and field drawn at random, as Version 2 XML.
pub fn generate(r: &mut Random) -> String {
    let mut x = String::from("<World Version=\"2\">");
    if r.chance(70) {
        element(&mut x, "Gravity", &vec2(r.float(), r.float()));
    }
    let shapes = 1 + r.below(6) as usize;
    x.push_str("<Shapes>");
    for _ in 0..shapes {
        shape(&mut x, r);
    }
    x.push_str("</Shapes><Fixtures>");
    let fixtures = 1 + r.below(6) as usize;
    for _ in 0..fixtures {
        fixture(&mut x, r, shapes);
    }
    x.push_str("</Fixtures><Bodies>");
    let bodies = 2 + r.below(5) as usize;
    for _ in 0..bodies {
        body(&mut x, r, fixtures);
    }
    x.push_str("</Bodies><Joints>");
    joints(&mut x, r, bodies);
    x.push_str("</Joints></World>");
    x
}

fn shape(x: &mut String, r: &mut Random) {
    let kind = r.pick(&["Circle", "Polygon", "Edge", "Chain", "Loop"]);
    let _ = write!(x, "<Shape Type=\"{kind}\">");
    named_shape(x, r);
    let scale = r.pick(&[0.01f32, 1.0, 1000.0]);
    match kind {
        "Circle" => {
            element(x, "Radius", &num(r.non_negative().max(f32::from_bits(1))));
            element(x, "Position", &vec2(r.float(), r.float()));
        }
        "Polygon" => {
            let n = 2 + r.below(7);
            x.push_str("<Vertices>");
            for k in 0..n {
                let angle = std::f32::consts::TAU * k as f32 / n as f32;
                element(x, "Vertex", &vec2(scale * angle.cos(), scale * angle.sin()));
            }
            x.push_str("</Vertices>");
            if r.chance(50) {
                element(x, "Centroid", &vec2(r.float(), r.float()));
            }
        }
        "Edge" => {
            element(x, "Vertex1", &vec2(-scale, r.ordinary(scale)));
            element(x, "Vertex2", &vec2(scale, r.ordinary(scale)));
            ghosts(x, r, ["Vertex0", "Vertex3", "HasVertex0", "HasVertex3"]);
        }
        _ => {
            // Consecutive chain vertices must be farther apart than the linear slop.
            let scale = scale.max(1.0);
            x.push_str("<Vertices>");
            for k in 0..3 + r.below(20) {
                let angle = std::f32::consts::TAU * k as f32 / 23.0;
                element(x, "Vertex", &vec2(scale * angle.cos(), scale * angle.sin()));
            }
            x.push_str("</Vertices>");
            ghosts(x, r, ["PrevVertex", "NextVertex", "HasPrevVertex", "HasNextVertex"]);
        }
    }
    x.push_str("</Shape>");
}

fn named_shape(x: &mut String, r: &mut Random) {
    if r.chance(50) {
        element(x, "Name", &escape(r.pick(NAMES)));
    }
}

fn ghosts(x: &mut String, r: &mut Random, names: [&str; 4]) {
    for name in &names[..2] {
        if r.chance(50) {
            element(x, name, &vec2(r.float(), r.float()));
        }
    }
    for name in &names[2..] {
        if r.chance(50) {
            element(x, name, if r.chance(50) { "True" } else { "false" });
        }
    }
}

fn fixture(x: &mut String, r: &mut Random, shapes: usize) {
    x.push_str("<Fixture>");
    element(x, "Shape", &r.below(shapes as u64).to_string());
    named(x, r);
    for name in ["Density", "Friction", "Restitution"] {
        if r.chance(60) {
            element(x, name, &num(r.non_negative()));
        }
    }
    if r.chance(50) {
        element(x, "IsSensor", if r.chance(50) { "1" } else { "0" });
    }
    if r.chance(50) {
        x.push_str("<FilterData>");
        element(x, "CategoryBits", &format!("0x{:X}", r.below(65536)));
        element(x, "MaskBits", &r.below(65536).to_string());
        element(x, "GroupIndex", &(r.below(65536) as i64 - 32768).to_string());
        x.push_str("</FilterData>");
    }
    x.push_str("</Fixture>");
}

fn body(x: &mut String, r: &mut Random, fixtures: usize) {
    let _ = write!(x, "<Body Type=\"{}\">", r.pick(&["Static", "Dynamic", "Kinematic"]));
    named(x, r);
    for name in ["Active", "AllowSleep", "Awake", "Bullet", "FixedRotation"] {
        if r.chance(40) {
            element(x, name, if r.chance(50) { "true" } else { "False" });
        }
    }
    for name in [
        "Angle",
        "AngularDamping",
        "AngularVelocity",
        "LinearDamping",
        "InertiaScale",
        "GravityScale",
    ] {
        if r.chance(40) {
            element(x, name, &num(r.float()));
        }
    }
    for name in ["LinearVelocity", "Position"] {
        if r.chance(50) {
            element(x, name, &vec2(r.float(), r.float()));
        }
    }
    if r.chance(30) {
        x.push_str("<MassData>");
        if r.chance(60) {
            element(x, "Mass", &num(r.non_negative()));
        }
        if r.chance(60) {
            element(x, "Center", &vec2(r.float(), r.float()));
        }
        if r.chance(60) {
            element(x, "Inertia", &num(r.non_negative()));
        }
        x.push_str("</MassData>");
    }
    x.push_str("<Fixtures>");
    for _ in 0..r.below(4) {
        element(x, "ID", &r.below(fixtures as u64).to_string());
    }
    x.push_str("</Fixtures></Body>");
}

/// Kind-specific elements: (name, what value).
fn joint_fields(kind: &str) -> &'static [(&'static str, char)] {
    // v = any vector, a = non-zero axis, f = any float, n = non-negative, b = bool,
    // p = positive (pulley ratio).
    match kind {
        "Revolute" => &[
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("ReferenceAngle", 'f'),
            ("EnableMotor", 'b'),
            ("MotorSpeed", 'f'),
            ("MaxMotorTorque", 'n'),
        ],
        "Prismatic" => &[
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("LocalAxisA", 'a'),
            ("ReferenceAngle", 'f'),
            ("EnableMotor", 'b'),
            ("MaxMotorForce", 'n'),
            ("MotorSpeed", 'f'),
        ],
        "Distance" => &[
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("Length", 'n'),
            ("FrequencyHz", 'n'),
            ("DampingRatio", 'n'),
        ],
        "Pulley" => &[
            ("GroundAnchorA", 'v'),
            ("GroundAnchorB", 'v'),
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("LengthA", 'f'),
            ("LengthB", 'f'),
            ("MaxLengthA", 'f'),
            ("MaxLengthB", 'f'),
            ("Ratio", 'p'),
        ],
        "Line" => &[
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("LocalAxisA", 'a'),
            ("EnableMotor", 'b'),
            ("MaxMotorForce", 'n'),
            ("MotorSpeed", 'f'),
        ],
        "Weld" => &[
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("ReferenceAngle", 'f'),
            ("FrequencyHz", 'n'),
            ("DampingRatio", 'n'),
        ],
        "Friction" => {
            &[("LocalAnchorA", 'v'), ("LocalAnchorB", 'v'), ("MaxForce", 'n'), ("MaxTorque", 'n')]
        }
        "Gear" => &[("Ratio", 'f')],
        "Wheel" => &[
            ("LocalAnchorA", 'v'),
            ("LocalAnchorB", 'v'),
            ("LocalAxisA", 'a'),
            ("EnableMotor", 'b'),
            ("MaxMotorTorque", 'n'),
            ("MotorSpeed", 'f'),
            ("FrequencyHz", 'n'),
            ("DampingRatio", 'n'),
        ],
        "Rope" => &[("LocalAnchorA", 'v'), ("LocalAnchorB", 'v'), ("MaxLength", 'n')],
        _ => &[
            ("LinearOffset", 'v'),
            ("AngularOffset", 'f'),
            ("MaxForce", 'n'),
            ("MaxTorque", 'n'),
            ("CorrectionFactor", 'f'),
        ],
    }
}

fn joints(x: &mut String, r: &mut Random, bodies: usize) {
    const KINDS: [&str; 11] = [
        "Revolute",
        "Prismatic",
        "Distance",
        "Pulley",
        "Line",
        "Weld",
        "Friction",
        "Gear",
        "Wheel",
        "Rope",
        "Motor",
    ];
    let count = r.below(8) as usize;
    // Revolute and prismatic joints first, so that gears have something to couple.
    let kinds: Vec<&str> =
        (0..count).map(|i| if i < 2 { KINDS[i] } else { r.pick(&KINDS) }).collect();
    for kind in kinds {
        let _ = write!(x, "<Joint Type=\"{kind}\">");
        named(x, r);
        let a = r.below(bodies as u64);
        let b = (a + 1 + r.below(bodies as u64 - 1)) % bodies as u64;
        element(x, "BodyA", &a.to_string());
        element(x, "BodyB", &b.to_string());
        if r.chance(30) {
            element(x, "CollideConnected", "True");
        }
        if kind == "Gear" {
            element(x, "JointA", &r.below(2).to_string());
            element(x, "JointB", &r.below(2).to_string());
        }
        if matches!(kind, "Revolute" | "Prismatic" | "Line") && r.chance(50) {
            let (lower, upper) = if kind == "Revolute" {
                ("LowerAngle", "UpperAngle")
            } else {
                ("LowerTranslation", "UpperTranslation")
            };
            let (low, high) = (r.float(), r.float());
            element(x, "EnableLimit", if r.chance(50) { "true" } else { "false" });
            element(x, lower, &num(low.min(high)));
            element(x, upper, &num(low.max(high)));
        }
        for &(name, what) in joint_fields(kind) {
            if !r.chance(60) {
                continue;
            }
            let text = match what {
                'v' => vec2(r.float(), r.float()),
                'a' => vec2(r.ordinary(1.0), 1.0 + r.ordinary(1.0).abs()),
                'f' => num(r.float()),
                'n' => num(r.non_negative()),
                'p' => num(r.non_negative().max(f32::from_bits(1))),
                _ => (if r.chance(50) { "true" } else { "false" }).to_string(),
            };
            element(x, name, &text);
        }
        x.push_str("</Joint>");
    }
}
