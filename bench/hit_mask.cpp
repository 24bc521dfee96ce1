// hit_mask: compares what two renders hit, pixel by pixel, for bench/implicit_bench.py.
//
//   hit_mask depth TEST.exr REFERENCE.exr [--tolerance T] [--diff OUT.png]
//       two kerf depth AOVs (a miss is +inf): pixels hit by one and not the other, and over the
//       pixels both hit the largest relative depth difference and how many exceed T.
//   hit_mask coverage KERF.exr POV.png [--diff OUT.png]
//       a kerf depth AOV against a POV-Ray image rendered with +UA (alpha >= 0.5 is a hit):
//       pixels POV-Ray misses where kerf hits (its holes), those whose 8 neighbours kerf also
//       hits (holes away from any silhouette, so not a half-pixel framing difference), and
//       pixels POV-Ray hits where kerf does not.
//   hit_mask alpha REFERENCE.png TEST.png [--diff OUT.png]
//       two POV-Ray images rendered with +UA (bench/displace_bench.py: POV-Ray at a given
//       max_gradient against itself at a generous one): pixels TEST misses where REFERENCE
//       hits (holes), those away from any silhouette, and pixels only TEST hits.
//   hit_mask --self-test
// --list FILE writes every disagreeing pixel as "i j first second" (inf = miss), and with depth
// every pixel beyond T too.
//
// Prints one JSON object. The diff image is red where only the first hits, green where only
// the second does, grey where both do. Reads images with OpenImageIO; nothing of kerf.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Mask {
    int width = 0, height = 0;
    std::vector<float> value;  // depth (inf = miss) or alpha
    std::vector<char> hit;
};

struct Counts {
    long both = 0, firstOnly = 0, secondOnly = 0, firstOnlyInterior = 0, overTolerance = 0;
    long firstHit = 0, secondHit = 0;
    double relMax = 0.0;
};

bool readChannel(const std::string& path, int channel, Mask& out) {
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
        std::fprintf(stderr, "hit_mask: cannot read %s: %s\n", path.c_str(),
                     image.geterror().c_str());
        return false;
    }
    const OIIO::ImageSpec& spec = image.spec();
    if (channel < 0) channel = spec.nchannels - 1;  // the last channel: alpha
    if (channel >= spec.nchannels) {
        std::fprintf(stderr, "hit_mask: %s has no channel %d\n", path.c_str(), channel);
        return false;
    }
    out.width = spec.width;
    out.height = spec.height;
    out.value.resize(size_t(out.width) * out.height);
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i)
            out.value[size_t(j) * out.width + i] = image.getchannel(i, j, 0, channel);
    return true;
}

void depthHits(Mask& m) {
    m.hit.resize(m.value.size());
    for (size_t k = 0; k < m.value.size(); ++k) m.hit[k] = std::isfinite(m.value[k]) ? 1 : 0;
}

void alphaHits(Mask& m) {
    m.hit.resize(m.value.size());
    for (size_t k = 0; k < m.value.size(); ++k) m.hit[k] = m.value[k] >= 0.5f ? 1 : 0;
}

// Whether every one of the 8 neighbours of (i, j) is hit (false at the image's border).
bool surrounded(const Mask& m, int i, int j) {
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            const int x = i + di, y = j + dj;
            if (x < 0 || y < 0 || x >= m.width || y >= m.height) return false;
            if (!m.hit[size_t(y) * m.width + x]) return false;
        }
    return true;
}

// Compares the masks; with depths, also the relative difference over the pixels both hit.
Counts compare(const Mask& a, const Mask& b, bool depths, double tolerance) {
    Counts c;
    for (int j = 0; j < a.height; ++j)
        for (int i = 0; i < a.width; ++i) {
            const size_t k = size_t(j) * a.width + i;
            c.firstHit += a.hit[k];
            c.secondHit += b.hit[k];
            if (a.hit[k] && b.hit[k]) {
                ++c.both;
                if (!depths) continue;
                const double rel = std::fabs(double(a.value[k]) - b.value[k]) / b.value[k];
                c.relMax = std::max(c.relMax, rel);
                if (rel > tolerance) ++c.overTolerance;
            } else if (a.hit[k]) {
                ++c.firstOnly;
                if (surrounded(a, i, j)) ++c.firstOnlyInterior;
            } else if (b.hit[k]) {
                ++c.secondOnly;
            }
        }
    return c;
}

bool writeList(const std::string& path, const Mask& a, const Mask& b, bool depths,
               double tolerance) {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        std::fprintf(stderr, "hit_mask: cannot write %s\n", path.c_str());
        return false;
    }
    for (int j = 0; j < a.height; ++j)
        for (int i = 0; i < a.width; ++i) {
            const size_t k = size_t(j) * a.width + i;
            const bool differ =
                a.hit[k] != b.hit[k] ||
                (depths && a.hit[k] &&
                 std::fabs(double(a.value[k]) - b.value[k]) > tolerance * b.value[k]);
            if (differ) std::fprintf(f, "%d %d %.9g %.9g\n", i, j, a.value[k], b.value[k]);
        }
    return std::fclose(f) == 0;
}

bool writeDiff(const std::string& path, const Mask& a, const Mask& b) {
    OIIO::ImageSpec spec(a.width, a.height, 3, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf out(spec);
    for (int j = 0; j < a.height; ++j)
        for (int i = 0; i < a.width; ++i) {
            const size_t k = size_t(j) * a.width + i;
            float rgb[3] = {0, 0, 0};
            if (a.hit[k] && b.hit[k])
                rgb[0] = rgb[1] = rgb[2] = 0.35f;
            else if (a.hit[k])
                rgb[0] = 1;
            else if (b.hit[k])
                rgb[1] = 1;
            out.setpixel(i, j, rgb);
        }
    if (!out.write(path)) {
        std::fprintf(stderr, "hit_mask: cannot write %s\n", path.c_str());
        return false;
    }
    return true;
}

Mask fromValues(int w, int h, std::vector<float> v, bool depth) {
    Mask m;
    m.width = w;
    m.height = h;
    m.value = std::move(v);
    depth ? depthHits(m) : alphaHits(m);
    return m;
}

// Hand-counted 3 x 3 cases: the counts the benchmark prints must mean what they say.
int selfTest() {
    const float inf = INFINITY;
    int failures = 0;
    auto expect = [&](bool ok, const char* what) {
        if (!ok) {
            std::fprintf(stderr, "hit_mask self-test failed: %s\n", what);
            ++failures;
        }
    };
    // First: 8 hits (the centre missed); second: the centre and the corner (0,0) missed, one
    // depth 10 % off. Expect both 7, firstOnly 1 (the corner), secondOnly 0, relMax 0.1.
    Mask a = fromValues(3, 3, {1, 1, 1, 1, inf, 1, 1, 1, 1}, true);
    Mask b = fromValues(3, 3, {inf, 1, 1, 1, inf, 1, 1, 1, 1.0f / 1.1f}, true);
    Counts c = compare(a, b, true, 0.05);
    expect(c.both == 7 && c.firstOnly == 1 && c.secondOnly == 0, "depth mask counts");
    expect(std::fabs(c.relMax - 0.1) < 1e-6 && c.overTolerance == 1, "depth difference");
    expect(c.firstOnlyInterior == 0, "a corner is never interior");
    // Coverage: kerf hits everything, POV-Ray (alpha) misses only the centre: an interior hole.
    Mask k = fromValues(3, 3, std::vector<float>(9, 2.0f), true);
    Mask p = fromValues(3, 3, {1, 1, 1, 1, 0.2f, 1, 1, 1, 1}, false);
    c = compare(k, p, false, 0);
    expect(c.firstOnly == 1 && c.firstOnlyInterior == 1 && c.secondOnly == 0, "interior hole");
    c = compare(p, k, false, 0);
    expect(c.secondOnly == 1 && c.firstOnly == 0 && c.both == 8, "the other way round");
    if (failures == 0) std::fprintf(stderr, "hit_mask self-test: ok\n");
    return failures == 0 ? 0 : 1;
}

int usage() {
    std::fprintf(stderr,
                 "usage: hit_mask depth TEST.exr REFERENCE.exr [--tolerance T] [--diff OUT.png] "
                 "[--list OUT.txt]\n"
                 "       hit_mask coverage KERF.exr POV.png [--diff OUT.png] [--list OUT.txt]\n"
                 "       hit_mask alpha REFERENCE.png TEST.png [--diff OUT.png] [--list OUT.txt]\n"
                 "       hit_mask --self-test\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::strcmp(argv[1], "--self-test") == 0) return selfTest();
    if (argc < 4) return usage();
    const std::string mode = argv[1];
    if (mode != "depth" && mode != "coverage" && mode != "alpha") return usage();
    const bool alphas = mode == "alpha";
    double tolerance = 0.0;
    std::string diff, list;
    for (int k = 4; k < argc; ++k) {
        if (std::strcmp(argv[k], "--tolerance") == 0 && k + 1 < argc)
            tolerance = std::atof(argv[++k]);
        else if (std::strcmp(argv[k], "--diff") == 0 && k + 1 < argc)
            diff = argv[++k];
        else if (std::strcmp(argv[k], "--list") == 0 && k + 1 < argc)
            list = argv[++k];
        else
            return usage();
    }
    const bool depths = mode == "depth";
    Mask a, b;
    if (!readChannel(argv[2], alphas ? -1 : 0, a) || !readChannel(argv[3], depths ? 0 : -1, b))
        return 1;
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "hit_mask: sizes differ (%dx%d, %dx%d)\n", a.width, a.height, b.width,
                     b.height);
        return 1;
    }
    alphas ? alphaHits(a) : depthHits(a);
    depths ? depthHits(b) : alphaHits(b);
    const Counts c = compare(a, b, depths, tolerance);
    if (!diff.empty() && !writeDiff(diff, a, b)) return 1;
    if (!list.empty() && !writeList(list, a, b, depths, tolerance)) return 1;
    if (depths)
        std::printf(
            "{\"pixels\": %ld, \"test_hit\": %ld, \"reference_hit\": %ld, \"both\": %ld, "
            "\"test_only\": %ld, \"reference_only\": %ld, \"rel_max\": %.9g, "
            "\"tolerance\": %.9g, \"over_tolerance\": %ld}\n",
            long(a.value.size()), c.firstHit, c.secondHit, c.both, c.firstOnly, c.secondOnly,
            c.relMax, tolerance, c.overTolerance);
    else if (alphas)
        std::printf(
            "{\"pixels\": %ld, \"reference_hit\": %ld, \"test_hit\": %ld, \"both\": %ld, "
            "\"test_missed\": %ld, \"test_missed_interior\": %ld, \"test_extra\": %ld}\n",
            long(a.value.size()), c.firstHit, c.secondHit, c.both, c.firstOnly, c.firstOnlyInterior,
            c.secondOnly);
    else
        std::printf(
            "{\"pixels\": %ld, \"kerf_hit\": %ld, \"pov_hit\": %ld, \"both\": %ld, "
            "\"pov_missed\": %ld, \"pov_missed_interior\": %ld, \"pov_extra\": %ld}\n",
            long(a.value.size()), c.firstHit, c.secondHit, c.both, c.firstOnly, c.firstOnlyInterior,
            c.secondOnly);
    return 0;
}
