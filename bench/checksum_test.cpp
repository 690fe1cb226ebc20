// bench/checksum_test [FILE...] [--warnings FILE...]: box2scene and each peer (on pugixml,
// on rapidxml) load each FILE (from bench/generate), and small generated scenes of many
// sizes and seeds, to the same counts and the same checksum of every value; box2scene
// without a warning, since the files are meant to load cleanly, except for files after
// --warnings (from bench/generate --warnings), which must give exactly the warnings the
// generator promises. And each peer refuses what box2scene refuses, for each check it
// makes.
#include <box2scene.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <string>

#include "file_bytes.hpp"
#include "pugi_loader.hpp"
#include "rapidxml_loader.hpp"
#include "scene_checksum.hpp"
#include "scene_generator.hpp"

namespace {

/// A peer loader, named as the messages name it.
struct Peer {
    const char* name;
    bool (*load_file)(const char* path, bench::PeerScene& peer, std::string& why);
    bool (*load_text)(const std::string& text, bench::PeerScene& peer, std::string& why);
};

/// pugixml parses in place the buffer it is given: a copy of the text.
bool pugi_load_text(const std::string& text, bench::PeerScene& peer, std::string& why) {
    std::unique_ptr<char[]> copy(new char[text.size()]);
    std::memcpy(copy.get(), text.data(), text.size());
    return bench::pugi_load(std::move(copy), text.size(), peer, why);
}

bool rapidxml_load_text(const std::string& text, bench::PeerScene& peer, std::string& why) {
    return bench::rapidxml_load(text.data(), text.size(), peer, why);
}

const Peer kPeers[] = {
    {"pugixml", bench::pugi_load_file, pugi_load_text},
    {"rapidxml", bench::rapidxml_load_file, rapidxml_load_text},
};
constexpr size_t kPeerCount = std::size(kPeers);

void print_counts(const char* who, const b2s_scene_view& v) {
    std::printf("  %-9s %u shapes, %u fixtures, %u bodies, %u joints, %u vertices, "
                "%u fixture IDs\n",
                who, v.shape_count, v.fixture_count, v.body_count, v.joint_count, v.vertex_count,
                v.fixture_id_count);
}

void print_parts(const char* who, const bench::SceneChecksum& c) {
    std::printf("  %-9s world %016" PRIx64 " shapes %016" PRIx64 " fixtures %016" PRIx64
                " bodies %016" PRIx64 " joints %016" PRIx64 " vertices %016" PRIx64
                " fixture IDs %016" PRIx64 "\n",
                who, c.world, c.shapes, c.fixtures, c.bodies, c.joints, c.vertices,
                c.fixture_ids);
}

/// Whether box2scene gives the warnings the generator promises: none, or one
/// `dynamic-body-zero-density` for each of a tenth of the bodies, capped as every scene's
/// warnings are; says what differs when it does not. The generator places the bodies of a
/// joint at random, so its joints start violated: `joint-starts-violated`, which comes
/// after the others, says so of the level, not of what was read, and is not counted.
bool expected_warnings(const std::string& what, const b2s_scene_view& view,
                       bench::Warnings warnings) {
    uint32_t warned = warnings == bench::Warnings::none ? 0 : view.body_count / 10;
    uint32_t kept = std::min<uint32_t>(warned, B2S_MAX_WARNINGS);
    uint32_t count = kept + (warned > kept ? 1 : 0); // and one warnings-truncated
    uint32_t given = view.diagnostic_count;
    while (given > count && view.diagnostics[given - 1].code != B2S_CODE_DYNAMIC_BODY_ZERO_DENSITY &&
           (view.diagnostics[given - 1].code == B2S_CODE_JOINT_STARTS_VIOLATED ||
            view.diagnostics[given - 1].code == B2S_CODE_WARNINGS_TRUNCATED)) {
        given -= 1;
    }
    bool as_promised = given == count;
    for (uint32_t i = 0; as_promised && i < count; ++i) {
        uint32_t code = i < kept ? B2S_CODE_DYNAMIC_BODY_ZERO_DENSITY : B2S_CODE_WARNINGS_TRUNCATED;
        as_promised = view.diagnostics[i].code == code;
    }
    if (!as_promised) {
        std::printf("FAIL %s: box2scene gives %u warnings, not %u; first: %s\n", what.c_str(),
                    given, count, given > 0 ? view.diagnostics[0].message : "none");
    }
    return as_promised;
}

/// Whether box2scene's load and that of every peer agree (`peers` in kPeers order); says
/// what differs when they do not.
bool same_scene(const std::string& what, const b2s_scene* scene, const bench::PeerScene* peers,
                bench::Warnings warnings) {
    const b2s_scene_view& view = *b2s_scene_get_view(scene);
    if (!expected_warnings(what, view, warnings)) {
        return false;
    }
    bench::SceneChecksum ours = bench::checksum(view);
    for (size_t i = 0; i < kPeerCount; ++i) {
        bench::SceneChecksum theirs = bench::checksum(peers[i].view());
        if (!(ours == theirs)) {
            std::printf("FAIL %s: box2scene and the %s peer load it differently\n", what.c_str(),
                        kPeers[i].name);
            print_counts("box2scene", view);
            print_counts(kPeers[i].name, peers[i].view());
            print_parts("box2scene", ours);
            print_parts(kPeers[i].name, theirs);
            return false;
        }
    }
    return true;
}

/// Whether loading `bytes`, the text of `path`, from memory with `threads` gives the scenes
/// `peers` hold.
bool same_from_memory(const char* path, const std::unique_ptr<char[]>& bytes, size_t size,
                      uint32_t threads, const bench::PeerScene* peers, bench::Warnings warnings) {
    b2s_load_options options = b2s_load_options_default();
    options.threads = threads;
    b2s_scene* scene = nullptr;
    b2s_error error;
    if (!bytes || b2s_load_memory(reinterpret_cast<const uint8_t*>(bytes.get()), size, &options,
                                  &scene, &error) != B2S_CODE_OK) {
        std::printf("FAIL %s: box2scene from memory, threads %u\n", path, threads);
        return false;
    }
    std::string what = std::string(path) + " from memory, threads " + std::to_string(threads);
    bool same = same_scene(what, scene, peers, warnings);
    b2s_scene_free(scene);
    return same;
}

/// The file loads alike from its path (a chunk at a time), and from memory on one thread
/// and, ten times, on as many as box2scene chooses (two from 1 MiB on).
bool check_file(const char* path, bench::Warnings warnings) {
    b2s_scene* scene = nullptr;
    b2s_error error;
    if (b2s_load_file(path, nullptr, &scene, &error) != B2S_CODE_OK) {
        std::printf("FAIL %s: box2scene: %u:%u: %s\n", path, error.line, error.column,
                    error.message);
        return false;
    }
    bench::PeerScene peers[kPeerCount];
    bool loaded = true;
    for (size_t i = 0; loaded && i < kPeerCount; ++i) {
        std::string why;
        loaded = kPeers[i].load_file(path, peers[i], why);
        if (!loaded) {
            std::printf("FAIL %s: %s peer: %s\n", path, kPeers[i].name, why.c_str());
        }
    }
    size_t size = 0;
    std::unique_ptr<char[]> bytes = bench::read_file(path, size);
    bool same = loaded && same_scene(path, scene, peers, warnings) &&
                same_from_memory(path, bytes, size, 1, peers, warnings);
    // Where the two threads meet depends on timing; wherever they meet, the scene is one.
    for (int run = 0; same && run < 10; ++run) {
        same = same_from_memory(path, bytes, size, 0, peers, warnings);
    }
    if (same) {
        const b2s_scene_view& v = *b2s_scene_get_view(scene);
        std::printf("ok   %s: %u shapes, %u fixtures, %u bodies, %u joints, %u warnings; "
                    "checksum %016" PRIx64 "\n",
                    path, v.shape_count, v.fixture_count, v.body_count, v.joint_count,
                    v.diagnostic_count, bench::checksum(v).combined());
    }
    b2s_scene_free(scene);
    return same;
}

b2s_code box2scene_load(const std::string& text, b2s_scene** scene, b2s_error& error) {
    return b2s_load_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), nullptr,
                           scene, &error);
}

/// Whether box2scene and every peer load `text` alike, box2scene with `warnings`.
bool check_text(const std::string& what, const std::string& text,
                bench::Warnings warnings = bench::Warnings::none) {
    b2s_scene* scene = nullptr;
    b2s_error error;
    if (box2scene_load(text, &scene, error) != B2S_CODE_OK) {
        std::printf("FAIL %s: box2scene: %u:%u: %s\n", what.c_str(), error.line, error.column,
                    error.message);
        return false;
    }
    bench::PeerScene peers[kPeerCount];
    bool loaded = true;
    for (size_t i = 0; loaded && i < kPeerCount; ++i) {
        std::string why;
        loaded = kPeers[i].load_text(text, peers[i], why);
        if (!loaded) {
            std::printf("FAIL %s: %s peer: %s\n", what.c_str(), kPeers[i].name, why.c_str());
        }
    }
    bool same = loaded && same_scene(what, scene, peers, warnings);
    b2s_scene_free(scene);
    return same;
}

// A small scene every loader takes, for the refusals below to change one part of.
const char* const kCircle =
    "<Shape Type='Circle'><Radius>1</Radius><Position>0 0</Position></Shape>";
const char* const kFixture = "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>";
const char* const kBodies =
    "<Body Type='Dynamic'><Fixtures><ID>0</ID></Fixtures></Body><Body Type='Static'/>";
const char* const kJoint = "<Joint Type='Revolute'><BodyA>1</BodyA><BodyB>0</BodyB></Joint>";

std::string scene(const std::string& shapes = kCircle, const std::string& fixtures = kFixture,
                  const std::string& bodies = kBodies, const std::string& joints = kJoint) {
    return "<World Version='2'><Shapes>" + shapes + "</Shapes><Fixtures>" + fixtures +
           "</Fixtures><Bodies>" + bodies + "</Bodies><Joints>" + joints + "</Joints></World>";
}

std::string fixture_with(const std::string& element) {
    return "<Fixture><Shape>0</Shape>" + element + "</Fixture>";
}

std::string joint(const char* type, const std::string& elements) {
    return std::string("<Joint Type='") + type + "'><BodyA>1</BodyA><BodyB>0</BodyB>" +
           elements + "</Joint>";
}

std::string polygon(const std::string& vertices) {
    return "<Shape Type='Polygon'><Vertices>" + vertices + "</Vertices></Shape>";
}

struct Refusal {
    const char* what;
    std::string text;
};

/// Whether box2scene and every peer refuse `r.text`; says which one did not.
bool all_refuse(const Refusal& r) {
    b2s_scene* scene = nullptr;
    b2s_error error;
    bool refused = box2scene_load(r.text, &scene, error) != B2S_CODE_OK;
    b2s_scene_free(scene);
    if (!refused) {
        std::printf("FAIL %s: box2scene loads it\n", r.what);
    }
    for (const Peer& peer : kPeers) {
        bench::PeerScene loaded;
        std::string why;
        if (peer.load_text(r.text, loaded, why)) {
            std::printf("FAIL %s: the %s peer loads it\n", r.what, peer.name);
            refused = false;
        }
    }
    return refused;
}

int check_refusals() {
    std::string nine_vertices;
    for (int k = 0; k < 9; ++k) {
        double angle = 6.283185307179586 * k / 9;
        nine_vertices += "<Vertex>" + std::to_string(std::cos(angle)) + " " +
                         std::to_string(std::sin(angle)) + "</Vertex>";
    }
    const Refusal refusals[] = {
        {"the base scene, made malformed", scene().substr(1)},
        {"an end tag that does not match", "<World Version='2'><Shapes></Bodies></World>"},
        {"a DOCTYPE", "<!DOCTYPE World>" + scene()},
        {"a second root", scene() + "<World Version='2'/>"},
        {"an unsupported version", "<World Version='7'/>"},
        {"a negative density", scene(kCircle, fixture_with("<Density>-1</Density>"))},
        {"a decimal comma", scene(kCircle, fixture_with("<Friction>0,5</Friction>"))},
        {"NaN", scene(kCircle, fixture_with("<Friction>NaN</Friction>"))},
        {"a float beyond f32", scene(kCircle, fixture_with("<Restitution>1e39</Restitution>"))},
        {"a boolean spelled yes", scene(kCircle, fixture_with("<IsSensor>yes</IsSensor>"))},
        {"a 17-bit group index",
         scene(kCircle, fixture_with("<FilterData><GroupIndex>40000</GroupIndex></FilterData>"))},
        {"a negative bit mask",
         scene(kCircle, fixture_with("<FilterData><MaskBits>-1</MaskBits></FilterData>"))},
        {"a fixture without a shape", scene(kCircle, "<Fixture><Density>1</Density></Fixture>")},
        {"a shape ID out of range", scene(kCircle, "<Fixture><Shape>5</Shape></Fixture>")},
        {"a negative fixture ID",
         scene(kCircle, kFixture, "<Body Type='Static'><Fixtures><ID>-1</ID></Fixtures></Body>")},
        {"a fixture ID out of range",
         scene(kCircle, kFixture, "<Body Type='Static'><Fixtures><ID>3</ID></Fixtures></Body>")},
        {"an unknown body type", scene(kCircle, kFixture, "<Body Type='Floating'/>")},
        {"a zero radius",
         scene("<Shape Type='Circle'><Radius>0</Radius><Position>0 0</Position></Shape>")},
        {"a circle without a position", scene("<Shape Type='Circle'><Radius>1</Radius></Shape>")},
        {"a three-number vector",
         scene("<Shape Type='Circle'><Radius>1</Radius><Position>1 2 3</Position></Shape>")},
        {"nine vertices", scene(polygon(nine_vertices))},
        {"a collinear polygon",
         scene(polygon("<Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>2 0</Vertex>"))},
        {"a joint on one body",
         scene(kCircle, kFixture, kBodies,
               "<Joint Type='Weld'><BodyA>0</BodyA><BodyB>0</BodyB></Joint>")},
        {"a body ID out of range",
         scene(kCircle, kFixture, kBodies,
               "<Joint Type='Weld'><BodyA>0</BodyA><BodyB>9</BodyB></Joint>")},
        {"a limit upside down",
         scene(kCircle, kFixture, kBodies,
               joint("Revolute", "<EnableLimit>true</EnableLimit><LowerAngle>1</LowerAngle>"
                                 "<UpperAngle>0</UpperAngle>"))},
        {"a zero axis", scene(kCircle, kFixture, kBodies,
                              joint("Prismatic", "<LocalAxisA>0 0</LocalAxisA>"))},
        {"a zero pulley ratio",
         scene(kCircle, kFixture, kBodies, joint("Pulley", "<Ratio>0</Ratio>"))},
        {"a gear coupling a weld",
         scene(kCircle, kFixture, kBodies,
               joint("Weld", "") + joint("Gear", "<JointA>0</JointA><JointB>0</JointB>"))},
        {"a mouse joint", scene(kCircle, kFixture, kBodies, joint("Mouse", ""))},
    };
    int failures = check_text("the base scene of the refusals", scene()) ? 0 : 1;
    for (const Refusal& r : refusals) {
        failures += all_refuse(r) ? 0 : 1;
    }
    if (failures == 0) {
        std::printf("ok   box2scene and every peer refuse each of %zu broken scenes\n",
                    std::size(refusals));
    }
    return failures;
}

} // namespace

int main(int argc, char** argv) {
    int failures = 0;
    bench::Warnings warnings = bench::Warnings::none;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--warnings") == 0) {
            warnings = bench::Warnings::tenth_of_bodies;
        } else {
            failures += check_file(argv[i], warnings) ? 0 : 1;
        }
    }
    // Small scenes reach the corners: no joints, empty containers, a lone gear's fallback,
    // too few fixtures to make exactly a tenth of the bodies warn.
    int generated = 0;
    for (uint32_t bodies = 0; bodies <= 60; ++bodies) {
        for (uint64_t seed = 1; seed <= 8; ++seed, generated += 2) {
            std::string what = std::to_string(bodies) + " bodies, seed " + std::to_string(seed);
            failures += check_text(what, bench::generate_scene(bodies, seed)) ? 0 : 1;
            bench::Warnings tenth = bench::Warnings::tenth_of_bodies;
            failures += check_text(what + ", with warnings",
                                   bench::generate_scene(bodies, seed, tenth), tenth)
                            ? 0
                            : 1;
        }
    }
    std::printf("%s %d generated scenes of 0 to 60 bodies\n", failures == 0 ? "ok  " : "FAIL",
                generated);
    failures += check_refusals();
    return failures == 0 ? 0 : 1;
}
