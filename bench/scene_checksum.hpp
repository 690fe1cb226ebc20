// A checksum of every value of a scene: counts, every float's bit pattern, every index and
// flag, names by content. Computed on a b2s_scene_view, so box2scene's scenes and the
// peers' (PeerScene::view) are summed by the same code.
#pragma once

#include <box2scene.h>

#include <cstdint>

namespace bench {

/// One FNV-1a sum per part of the scene, so that a difference says where it is.
struct SceneChecksum {
    uint64_t world;    ///< version, gravity, and the count of every array
    uint64_t shapes;
    uint64_t fixtures;
    uint64_t bodies;
    uint64_t joints;
    uint64_t vertices;
    uint64_t fixture_ids;

    /// The sum of the parts.
    uint64_t combined() const;
    bool operator==(const SceneChecksum& other) const;
};

/// Diagnostics are left out: they are box2scene's alone (the peer keeps none).
SceneChecksum checksum(const b2s_scene_view& view);

} // namespace bench
