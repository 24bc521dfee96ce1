// libFuzzer target: bytes -> an image file -> io/texture (Texture::open, then lookups). The
// first byte picks the format by extension (.png, .jpg, .exr, .tif, .hdr); the rest is the
// file, written to a fresh name each time (the plug-in keeps every opened texture under its
// path). A TextureError is the expected answer to a bad file; any crash, sanitizer report,
// hang (-timeout) or blow-up (-rss_limit_mb) is a bug. The image plug-in is loaded from
// beside this executable, built in the same tree with the same instrumentation.
#include "io/image_plugin_loader.h"
#include "io/texture.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

/// A scratch folder of this process's, made once.
const std::filesystem::path& fuzzTextureFolder() {
    static const std::filesystem::path folder = [] {
        std::filesystem::path p = std::filesystem::temp_directory_path() /
                                  ("kerf-fuzz-texture-" + std::to_string(::getpid()));
        std::filesystem::create_directories(p);
        return p;
    }();
    return folder;
}

void lookAround(const kerf::Texture& texture) {
    using Wrap = kerf::Texture::Wrap;
    (void)texture.lookup(0.5, 0.5, 0.0, 0.0, 0.0, 0.0);
    (void)texture.lookup(0.1, 0.9, 0.01, 0.0, 0.0, 0.01, Wrap::Clamp, Wrap::Periodic);
    (void)texture.lookup(-3.7, 12.2, 2.0, 0.5, -0.5, 0.25);
    (void)texture.lookup(1e30, -1e30, 1e30, 0.0, 0.0, 1e-30, Wrap::Clamp, Wrap::Clamp);
}

}  // namespace

/// OpenImageIO 2.4's PNG reader (PNGInput::PngReadCallback) takes its error text into a
/// std::string, then png_error longjmps past its destructor: 31 bytes per short PNG, in
/// OpenImageIO, not kerf (tests/sanitizers/lsan.supp names it for the sanitizer build too).
extern "C" const char* __lsan_default_suppressions() { return "leak:PNGInput::PngReadCallback\n"; }

/// Full stacks for allocations: OpenImageIO and libstdc++ have no frame pointers, so the fast
/// unwinder stops at libstdc++ and the suppression above could not see OpenImageIO's frame.
extern "C" const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }

/// Loads the plug-in (OpenImageIO and its ~260 libraries) before the first input, so that input
/// is not charged 4 s of start-up under the sanitizers: in fork mode each job is a new process,
/// and at a load of 4 that first input passed the 10 s timeout (17 false timeouts in an hour).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    kerf::requireImagePlugin();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1 || size > 64 * 1024) return -1;
    static const char* const kExtensions[] = {".png", ".jpg", ".exr", ".tif", ".hdr"};
    static unsigned long serial = 0;
    const std::filesystem::path file =
        fuzzTextureFolder() / ("input-" + std::to_string(serial++) + kExtensions[data[0] % 5]);
    {
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    try {
        lookAround(*kerf::Texture::open(file.string()));
    } catch (const kerf::TextureError&) {
        // the expected answer to a bad file
    }
    std::error_code ec;
    std::filesystem::remove(file, ec);
    return 0;
}
