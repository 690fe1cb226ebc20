//! One to several MiB of scene, made by editing a valid scene of many bodies where the input
//! says,
//! so that the two-thread load and the windowed read of a file run on inputs that libFuzzer
//! could never grow itself: memory on one thread, on two and from a file give the same
//! answer.
#![no_main]

use std::sync::OnceLock;

use box2scene::LoadOptions;
use libfuzzer_sys::fuzz_target;

#[path = "same.rs"]
mod same;

/// A Version 2 scene of 1.1 MiB (enough for two threads) times `size` (1 to 3): every kind
/// of item, repeated, each body different.
fn base(size: usize) -> &'static [u8] {
    static BASES: [OnceLock<Vec<u8>>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    BASES[size - 1].get_or_init(|| {
        let mut xml = String::from(
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<World Version=\"2\">\n  <Shapes>\n    \
             <Shape Type=\"Circle\"><Radius>0.5</Radius><Position>0 0</Position></Shape>\n    \
             <Shape Type=\"Polygon\"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex>\
             <Vertex>0 1</Vertex></Vertices></Shape>\n  </Shapes>\n  <Fixtures>\n    \
             <Fixture><Shape>0</Shape><Density>1</Density></Fixture>\n    \
             <Fixture><Shape>1</Shape><Friction>0.5</Friction></Fixture>\n  </Fixtures>\n  <Bodies>\n",
        );
        for i in 0..4_400 * size {
            xml.push_str(&format!(
                "    <Body Type=\"Dynamic\" Name=\"b{i}\">\n      <Position>{i}.5 -1.25</Position>\
                 <!-- c{i} -->\n      <Angle>0.{i}</Angle>\n      \
                 <UserData><Type>T</Type><Value><x a=\"{i}\">&amp;{i}</x></Value></UserData>\n      \
                 <Fixtures><ID>{}</ID></Fixtures>\n    </Body>\n",
                i % 2
            ));
        }
        xml.push_str("  </Bodies>\n  <Joints>\n");
        for i in 0..400 {
            xml.push_str(&format!(
                "    <Joint Type=\"Distance\"><BodyA>{i}</BodyA><BodyB>{}</BodyB>\
                 <Length>1</Length></Joint>\n",
                i + 1
            ));
        }
        xml.push_str("  </Joints>\n</World>\n");
        xml.into_bytes()
    })
}

fuzz_target!(|data: &[u8]| {
    // The size of the scene, then edits of five bytes each: where (scaled to the scene),
    // how many bytes to remove (0-7), and a byte to put in their place (none when its top
    // bit is set).
    let Some((&size, edits)) = data.split_first() else { return };
    let mut bytes = base(1 + usize::from(size % 3)).to_vec();
    for edit in edits.chunks_exact(5) {
        let at = u32::from_le_bytes([edit[0], edit[1], edit[2], 0]) as usize;
        let at = at * bytes.len() / (1 << 24);
        let remove = usize::from(edit[3] & 7).min(bytes.len() - at);
        let put = (edit[4] & 0x80 == 0).then_some(edit[4]);
        bytes.splice(at..at + remove, put);
    }
    same::check(&bytes, &LoadOptions::default());
});
