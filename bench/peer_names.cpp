#include "peer_names.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace bench::peer {
namespace {

struct Known {
    const char* lower;
    Name name;
};

constexpr Known kKnown[] = {
    {"world", Name::world}, {"gravity", Name::gravity}, {"shapes", Name::shapes},
    {"fixtures", Name::fixtures}, {"bodies", Name::bodies}, {"joints", Name::joints},
    {"shape", Name::shape}, {"fixture", Name::fixture}, {"body", Name::body},
    {"joint", Name::joint}, {"vertices", Name::vertices}, {"vertex", Name::vertex},
    {"id", Name::id}, {"name", Name::name}, {"radius", Name::radius},
    {"position", Name::position}, {"centroid", Name::centroid}, {"density", Name::density},
    {"friction", Name::friction}, {"restitution", Name::restitution},
    {"issensor", Name::is_sensor}, {"filterdata", Name::filter_data},
    {"categorybits", Name::category_bits}, {"maskbits", Name::mask_bits},
    {"groupindex", Name::group_index}, {"active", Name::active},
    {"allowsleep", Name::allow_sleep}, {"awake", Name::awake}, {"bullet", Name::bullet},
    {"fixedrotation", Name::fixed_rotation}, {"angle", Name::angle},
    {"angulardamping", Name::angular_damping}, {"angularvelocity", Name::angular_velocity},
    {"lineardamping", Name::linear_damping}, {"linearvelocity", Name::linear_velocity},
    {"inertiascale", Name::inertia_scale}, {"gravityscale", Name::gravity_scale},
    {"massdata", Name::mass_data}, {"mass", Name::mass}, {"center", Name::center},
    {"inertia", Name::inertia}, {"bodya", Name::body_a}, {"bodyb", Name::body_b},
    {"jointa", Name::joint_a}, {"jointb", Name::joint_b},
    {"collideconnected", Name::collide_connected}, {"localanchora", Name::local_anchor_a},
    {"localanchorb", Name::local_anchor_b}, {"localaxisa", Name::local_axis_a},
    {"referenceangle", Name::reference_angle}, {"enablelimit", Name::enable_limit},
    {"lowerangle", Name::lower_angle}, {"upperangle", Name::upper_angle},
    {"lowertranslation", Name::lower_translation},
    {"uppertranslation", Name::upper_translation}, {"enablemotor", Name::enable_motor},
    {"motorspeed", Name::motor_speed}, {"maxmotortorque", Name::max_motor_torque},
    {"maxmotorforce", Name::max_motor_force}, {"length", Name::length},
    {"frequencyhz", Name::frequency_hz}, {"dampingratio", Name::damping_ratio},
    {"groundanchora", Name::ground_anchor_a}, {"groundanchorb", Name::ground_anchor_b},
    {"lengtha", Name::length_a}, {"lengthb", Name::length_b},
    {"maxlengtha", Name::max_length_a}, {"maxlengthb", Name::max_length_b},
    {"ratio", Name::ratio}, {"maxforce", Name::max_force}, {"maxtorque", Name::max_torque},
    {"maxlength", Name::max_length}, {"linearoffset", Name::linear_offset},
    {"angularoffset", Name::angular_offset}, {"correctionfactor", Name::correction_factor},
};
constexpr size_t kKnownCount = sizeof kKnown / sizeof kKnown[0];
static_assert(kKnownCount + 1 == static_cast<size_t>(Name::count), "every name is known");

/// ASCII letters fold to lower case by setting bit 5; the known names are letters only,
/// and no other byte folds onto a letter.
constexpr unsigned char fold(char c) { return static_cast<unsigned char>(c) | 0x20; }

/// Open addressing, linear probing; a power of two well above the name count keeps probe
/// sequences short. Slots hold an index into kKnown plus one (0 = empty).
class NameTable {
public:
    NameTable() {
        for (size_t k = 0; k < kKnownCount; ++k) {
            size_t length = 0;
            size_t slot = hash(kKnown[k].lower, length) & kMask;
            while (slots_[slot] != 0) {
                slot = (slot + 1) & kMask;
            }
            slots_[slot] = static_cast<uint8_t>(k + 1);
        }
    }

    Name find(const char* tag) const {
        size_t length = 0;
        for (size_t slot = hash(tag, length) & kMask; slots_[slot] != 0;
             slot = (slot + 1) & kMask) {
            const Known& known = kKnown[slots_[slot] - 1];
            if (matches(tag, length, known.lower)) {
                return known.name;
            }
        }
        return Name::unknown;
    }

private:
    static constexpr size_t kSlots = 512;
    static constexpr size_t kMask = kSlots - 1;

    /// FNV-1a of the folded bytes, and the length on the way.
    static size_t hash(const char* text, size_t& length) {
        uint64_t h = 0xCBF29CE484222325u;
        const char* p = text;
        for (; *p != '\0'; ++p) {
            h = (h ^ fold(*p)) * 0x100000001B3u;
        }
        length = static_cast<size_t>(p - text);
        return static_cast<size_t>(h ^ (h >> 29));
    }

    static bool matches(const char* tag, size_t length, const char* lower) {
        for (size_t i = 0; i < length; ++i) {
            if (fold(tag[i]) != static_cast<unsigned char>(lower[i])) {
                return false; // also at lower's NUL, shorter than the tag
            }
        }
        return lower[length] == '\0';
    }

    std::array<uint8_t, kSlots> slots_{};
};

const NameTable kTable;

} // namespace

Name element_name(const char* tag) { return kTable.find(tag); }

} // namespace bench::peer
