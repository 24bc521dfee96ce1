// `kerf mesh` writes what kerf reads back as a solid (issue 24 §5): models of models/ meshed,
// written and read again by `kerf check`, with no boundary and no non-manifold edge. Before
// the crease points were unpinched (volume/export/mesh_unpinch.h), gyroid_sphere had 37
// edges of four faces and displace 14 (at voxel 0.05). Not yet in the list, because they still
// fail: box_minus_spheres, cup, showcase and mesh_csg, whose faces lie on lattice planes
// (48, 91, 364 and 1 non-manifold edges in the STL at voxel 0.05).
#include "kerf_runner.h"

#include <catch2/catch.hpp>

using namespace kerf::test;

namespace {

void requireReadBackSolid(const std::string& model, const std::string& format) {
    INFO(model << " as " << format);
    TempDir dir;
    const std::string mesh = model + "." + format;
    const KerfRun made = runKerf(dir, {"mesh", "-q", (modelsDir() / (model + ".kerf")).string(),
                                       "-o", mesh, "--voxel", "0.08"});
    INFO(made.err);
    REQUIRE(made.exitCode == 0);
    dir.write("back.kerf", "object mesh \"" + mesh + "\";\n");
    const KerfRun checked = runKerf(dir, {"check", "back.kerf"});
    INFO(checked.out << checked.err);
    REQUIRE(checked.exitCode == 0);
    CHECK(checked.out.find("boundary edges:       0\n") != std::string::npos);
    CHECK(checked.out.find("non-manifold edges:   0\n") != std::string::npos);
    CHECK(checked.out.find("solid:                yes\n") != std::string::npos);
}

}  // namespace

TEST_CASE("kerf mesh/gyroid_sphere reads back as a solid from OBJ, PLY and STL") {
    for (const char* format : {"obj", "ply", "stl"}) requireReadBackSolid("gyroid_sphere", format);
}

TEST_CASE("kerf mesh/displace and gear read back as solids from STL") {
    for (const char* model : {"displace", "gear"}) requireReadBackSolid(model, "stl");
}
