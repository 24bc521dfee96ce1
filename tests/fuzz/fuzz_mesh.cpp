// libFuzzer target for the mesh loader: the first byte chooses the format (by extension),
// the rest is written to a temporary file of that extension in a fresh folder, which loadMesh
// reads. A MeshError is the expected outcome of most inputs; anything else (a crash, a
// sanitizer report, another exception, a hang or a blow-up) is a finding.
#include "mesh/mesh_loader.h"

#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <string>

namespace {

const char* const kFuzzMeshExtensions[] = {".obj", ".ply", ".stl", ".gltf", ".glb", ".off"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1 || size > 64 * 1024) return 0;
    const char* ext = kFuzzMeshExtensions[data[0] % std::size(kFuzzMeshExtensions)];
    // A folder of its own, so a file the input names beside it (mtllib, a buffer) is absent.
    char folder[] = "/tmp/kerf_fuzz_mesh_XXXXXX";
    if (mkdtemp(folder) == nullptr) return 0;
    std::string path = std::string(folder) + "/inputXXXXXX" + ext;
    const int fd = mkstemps(path.data(), int(std::strlen(ext)));
    if (fd >= 0) {
        const bool written = write(fd, data + 1, size - 1) == ssize_t(size - 1);
        close(fd);
        try {
            if (written) kerf::loadMesh(path);
        } catch (const kerf::MeshError&) {
        }
        std::remove(path.c_str());
    }
    rmdir(folder);
    return 0;
}
