// The media benchmark's helper (bench/run_media_bench.sh): writes the fog volume both kerf and
// OpenVDB's vdb_render read, and measures images against a reference. It links OpenVDB and
// OpenImageIO and nothing of kerf.
//   media_bench write-fog OUT.vdb [N]       a noisy smoke cloud on an N³ grid over [-1, 1]³
//   media_bench const IMAGE T               transmittance error of channel 0 against T
//   media_bench trans REF TEST [--alpha]    transmittance error of TEST against REF (kerf
//                                           images: T in channel 0; --alpha: TEST is a
//                                           vdb_render EXR, T = 1 − alpha); both row orders
//   media_bench rmse REF TEST               RGB RMSE of TEST against REF
#include <OpenImageIO/imageio.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

uint64_t mix(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// Value noise in [0, 1): a hashed lattice value, smoothly interpolated.
double lattice(int x, int y, int z) {
    const uint64_t h = mix(uint64_t(uint32_t(x)) ^ mix(uint64_t(uint32_t(y)) ^ mix(uint32_t(z))));
    return double(h >> 11) * 0x1.0p-53;
}
double valueNoise(double x, double y, double z) {
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    auto s = [](double t) { return t * t * (3 - 2 * t); };
    const double fx = s(x - ix), fy = s(y - iy), fz = s(z - iz);
    double v = 0;
    for (int n = 0; n < 8; ++n)
        v += (n & 1 ? fx : 1 - fx) * (n & 2 ? fy : 1 - fy) * (n & 4 ? fz : 1 - fz) *
             lattice(ix + (n & 1), iy + ((n >> 1) & 1), iz + ((n >> 2) & 1));
    return v;
}

int writeFog(const char* out, int n) {
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    const double voxel = 2.0 / n;
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->setName("density");
    auto acc = grid->getAccessor();
    for (int k = -n / 2; k < n / 2; ++k)
        for (int j = -n / 2; j < n / 2; ++j)
            for (int i = -n / 2; i < n / 2; ++i) {
                const double x = i * voxel, y = j * voxel, z = k * voxel;
                // An off-centre lumpy cloud: a falloff from a centre shifted up and left,
                // modulated by two octaves of noise.
                const double r = std::sqrt((x + 0.15) * (x + 0.15) + (y - 0.1) * (y - 0.1) + z * z);
                const double fbm = valueNoise(4 * x + 10, 4 * y, 4 * z) +
                                   0.5 * valueNoise(8 * x, 8 * y + 5, 8 * z);
                const double d =
                    std::min(1.0, std::max(0.0, 1.6 * (0.8 - r) + 0.6 * (fbm - 0.75)) * 2.0);
                if (d > 0.0) acc.setValue(openvdb::Coord(i, j, k), float(d));
            }
    openvdb::io::File file(out);
    file.write({grid});
    file.close();
    std::printf("wrote %s: %d^3 grid, voxel %g, %llu active voxels\n", out, n, voxel,
                (unsigned long long)grid->activeVoxelCount());
    return 0;
}

struct Image {
    int w = 0, h = 0, c = 0;
    std::vector<float> p;
    float at(int x, int y, int ch) const { return p[(size_t(y) * w + x) * c + ch]; }
};

bool read(const char* path, Image& im) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        std::fprintf(stderr, "cannot read %s\n", path);
        return false;
    }
    const OIIO::ImageSpec& s = in->spec();
    im.w = s.width, im.h = s.height, im.c = s.nchannels;
    im.p.resize(size_t(im.w) * im.h * im.c);
    in->read_image(0, 0, 0, im.c, OIIO::TypeDesc::FLOAT, im.p.data());
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 3 && !std::strcmp(argv[1], "write-fog"))
        return writeFog(argv[2], argc > 3 ? std::atoi(argv[3]) : 256);
    if (argc >= 4 && !std::strcmp(argv[1], "const")) {
        Image im;
        if (!read(argv[2], im)) return 1;
        const double t = std::atof(argv[3]);
        double sum = 0, sum2 = 0, worst = 0;
        for (int y = 0; y < im.h; ++y)
            for (int x = 0; x < im.w; ++x) {
                const double e = im.at(x, y, 0) - t;
                sum += e, sum2 += e * e, worst = std::max(worst, std::fabs(e));
            }
        const double n = double(im.w) * im.h;
        std::printf("rmse %.3e mean %.3e max %.3e\n", std::sqrt(sum2 / n), sum / n, worst);
        return 0;
    }
    if (argc >= 4 && (!std::strcmp(argv[1], "trans") || !std::strcmp(argv[1], "rmse"))) {
        Image ref, test;
        if (!read(argv[2], ref) || !read(argv[3], test)) return 1;
        if (ref.w != test.w || ref.h != test.h) {
            std::fprintf(stderr, "sizes differ\n");
            return 1;
        }
        const bool alpha = argc > 4 && !std::strcmp(argv[4], "--alpha");
        const bool rgb = !std::strcmp(argv[1], "rmse");
        for (int flip = 0; flip < 2; ++flip) {
            double sum2 = 0, worst = 0, sum = 0;
            size_t count = 0;
            for (int y = 0; y < ref.h; ++y)
                for (int x = 0; x < ref.w; ++x) {
                    const int ty = flip ? ref.h - 1 - y : y;
                    for (int ch = 0; ch < (rgb ? 3 : 1); ++ch) {
                        const double r = ref.at(x, y, ch);
                        const double t = alpha ? 1.0 - test.at(x, ty, 3) : test.at(x, ty, ch);
                        const double e = t - r;
                        sum += e, sum2 += e * e, worst = std::max(worst, std::fabs(e));
                        ++count;
                    }
                }
            std::printf("%s rmse %.3e mean %.3e max %.3e\n", flip ? "flipped" : "as-is  ",
                        std::sqrt(sum2 / count), sum / count, worst);
            if (!alpha) break;
        }
        return 0;
    }
    std::fprintf(stderr, "usage: see the comment at the top of bench/media_bench.cpp\n");
    return 2;
}
