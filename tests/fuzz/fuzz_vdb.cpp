// libFuzzer target: bytes -> a temporary .vdb file -> the level-set and fog readers
// (volume/grids/vdb_level_set.h, vdb_fog.h), the entry points a model's `volume "x.vdb"` and
// `fog` use through the asset cache. A reader's error (VdbError, VdbFogError) is the expected
// answer to a bad file; any other exception, a crash, a sanitizer report, a hang or a large
// allocation is a bug. For a level set that loads, one ray is walked through it.
#include "volume/grids/level_set_node.h"
#include "volume/grids/vdb_fog.h"
#include "volume/grids/vdb_level_set.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

/// One file per process, rewritten for each input (libFuzzer runs inputs one at a time).
const std::string& fuzzVdbPath() {
    static const std::string path = [] {
        const char* dir = std::getenv("TMPDIR");
        return std::string(dir && *dir ? dir : "/tmp") + "/kerf-fuzz-vdb-" +
               std::to_string(getpid()) + ".vdb";
    }();
    return path;
}

bool writeFuzzVdb(const uint8_t* data, size_t size) {
    std::FILE* f = std::fopen(fuzzVdbPath().c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

void walkOneRay(const std::shared_ptr<const kerf::LevelSetGrid>& grid) {
    const kerf::NodePtr leaf = kerf::levelSetLeaf(grid);
    const kerf::Bounds3& b = grid->insideBounds();
    const kerf::Vec3 c = 0.5 * (b.lo + b.hi);
    kerf::TraceContext ctx;
    kerf::Boundary hit;
    bool entering = false;
    (void)leaf->firstSurface({c - kerf::Vec3(1e3, 0.5, 0.25), kerf::Vec3(1.0, 0.0, 0.0)}, 0.0,
                             kerf::kInf, ctx, hit, entering);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 64 * 1024 || !writeFuzzVdb(data, size)) return -1;
    try {
        walkOneRay(kerf::loadLevelSet(fuzzVdbPath()));
    } catch (const kerf::VdbError&) {
    }
    try {
        (void)kerf::loadVdbFog(fuzzVdbPath(), "");
    } catch (const kerf::VdbFogError&) {
    }
    std::remove(fuzzVdbPath().c_str());
    return 0;
}
