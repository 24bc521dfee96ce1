// A texture is refused on its header when it claims more pixels than a texture may have
// (KERF_TEXTURE_MAX_SIDE, KERF_TEXTURE_MAX_TEXELS in io/image_plugin.h), before any pixel is
// allocated: each format's 30,000 × 30,000 header (66 bytes to 8 KB) is exit 2 naming the
// file, and kerf's peak memory stays within a tiny valid texture's plus 4× the file plus
// kTextureHeaderSlack. Before the check a PNG header asked for 10.8 GB, a JPEG header ran
// past a minute at 7 GB and a TIFF header was read as "ok" after 19 s and 7 GB.
#include "app/exit_codes.h"
#include "io/image.h"
#include "kerf_peak_memory.h"
#include "util/hostile_image_headers.h"
#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// What a refused texture may cost above the baseline besides 4× its bytes: the plug-in's
/// reader state (libtiff, OpenEXR's offset table). Measured: within 1 MB of the baseline.
constexpr int64_t kTextureHeaderSlack = 64ll << 20;

std::string modelTexturing(const std::string& file) {
    return "camera { eye <0, 0, -4> look_at <0, 0, 0> fov 40 }\n"
           "material tex { pattern image { file \"" +
           file +
           "\" mapping planar } ambient 1 diffuse 0 specular 0 }\n"
           "object box { min <-1, -1, -1> max <1, 1, 1> } material tex;\n";
}

struct HostileTexture {
    const char* extension;
    std::function<std::string()> bytes;
};

}  // namespace

TEST_CASE("kerf check: a texture header claiming 30000 x 30000 is refused with bounded memory") {
    const HostileTexture cases[] = {
        {".png", [] { return pngHeaderClaiming(30000, 30000); }},
        {".jpg", [] { return jpegHeaderClaiming(30000, 30000); }},
        {".tif", [] { return tiffHeaderClaiming(30000, 30000); }},
        {".exr", [] { return exrHeaderClaiming(30000, 30000); }},
    };
    for (const HostileTexture& hostile : cases) {
        TempDir dir;
        const std::string ext = hostile.extension;
        writeImage(Image(4, 4, 3), (dir.path() / ("tiny" + ext)).string());
        dir.write("tiny.kerf", modelTexturing("tiny" + ext));
        const std::string bytes = hostile.bytes();
        dir.write("huge" + ext, bytes);
        dir.write("huge.kerf", modelTexturing("huge" + ext));

        const KerfPeakRun baseline = runKerfMeasuringPeak(dir, {"check", "tiny.kerf"});
        const KerfPeakRun run = runKerfMeasuringPeak(dir, {"check", "huge.kerf"});
        INFO(ext << " stderr:\n" << run.err << "\nbaseline stderr:\n" << baseline.err);
        REQUIRE(baseline.exitCode == 0);
        CHECK(run.exitCode == app::kExitUsage);
        CHECK_THAT(run.err, Catch::Contains("huge.kerf:2:") &&
                                Catch::Contains("cannot read texture 'huge" + ext +
                                                "': its header says 30000 x 30000 pixels"));
        CHECK_THAT(run.err, !Catch::Contains("libpng") && !Catch::Contains("TIFF"));
        if (!kUnderAddressSanitizer) {
            INFO("peak " << run.peakRss << " bytes, baseline " << baseline.peakRss << ", file "
                         << bytes.size());
            CHECK(run.peakRss <=
                  baseline.peakRss + 4 * int64_t(bytes.size()) + kTextureHeaderSlack);
        }
    }
}

TEST_CASE("kerf check: a texture at the size limit's side is read, one past it is refused") {
    TempDir dir;
    // 16384 × 1: the side limit itself, tiny in bytes; 16385 × 1 is one texel too wide.
    writeImage(Image(16384, 1, 1), (dir.path() / "wide.png").string());
    writeImage(Image(16385, 1, 1), (dir.path() / "wider.png").string());
    dir.write("wide.kerf", modelTexturing("wide.png"));
    dir.write("wider.kerf", modelTexturing("wider.png"));
    const KerfRun wide = runKerf(dir, {"check", "wide.kerf"});
    const KerfRun wider = runKerf(dir, {"check", "wider.kerf"});
    INFO(wide.err << wider.err);
    CHECK(wide.exitCode == 0);
    CHECK(wider.exitCode == app::kExitUsage);
    CHECK_THAT(wider.err, Catch::Contains("'wider.png': its header says 16385 x 1 pixels; a "
                                          "texture may have at most 16384 a side"));
}

// libpng's default error handler printed "libpng error: ..." ahead of kerf's message, since
// OpenImageIO's handler returns (io/png_errors_quiet.cpp now longjmps for it, silently).
TEST_CASE("kerf check: a corrupt PNG texture is kerf's one-line message, no libpng line") {
    TempDir dir;
    writeImage(Image(4, 4, 3), (dir.path() / "good.png").string());
    const std::string good = test::slurp((dir.path() / "good.png").string());
    const size_t idat = good.find("IDAT");
    REQUIRE(idat != std::string::npos);
    std::string crc = good;
    crc[idat + 6] = char(crc[idat + 6] ^ 0x5a);  // the data no longer matches the chunk's CRC
    dir.write("crc.png", crc);
    dir.write("cut.png", good.substr(0, idat + 10));  // ends inside the image data
    // The cut file makes OpenImageIO's PNG read callback leak 31 bytes (tests/sanitizers/
    // lsan.supp), which the sanitizer build's fast unwinder cannot attribute: release only.
    std::vector<std::string> names = {"crc.png"};
    if (!kUnderAddressSanitizer) names.push_back("cut.png");
    for (const std::string& name : names) {
        dir.write("t.kerf", modelTexturing(name));
        const KerfRun run = runKerf(dir, {"check", "t.kerf"});
        INFO(run.err);
        CHECK(run.exitCode == app::kExitUsage);
        CHECK(run.err.rfind("t.kerf:2:", 0) == 0);  // kerf's message comes first
        CHECK_THAT(run.err, Catch::Contains("cannot read texture '" + name + "'"));
        CHECK_THAT(run.err, !Catch::Contains("libpng"));
        const std::string firstLine = run.err.substr(0, run.err.find('\n'));
        CHECK_THAT(firstLine, Catch::Contains("PNG"));
    }
}
