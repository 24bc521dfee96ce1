// Image textures (`pattern image`, render/pattern_eval.h) against the texels written: each
// mapping puts a known texel at a known world point (the formulas of docs/language.md,
// "Image textures", written out again here), and a checkerboard image on a floor to the
// horizon does not alias at one sample per pixel (the procedural checker's test, mirrored).
#include "io/image.h"
#include "io/srgb.h"
#include "io/texture.h"
#include "render/camera.h"
#include "render/pattern_eval.h"
#include "render/render.h"
#include "render_test_util.h"

#include <catch2/catch.hpp>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr int kW = 16, kH = 9;  // odd height: the equator is a row's centre

/// A 16 × 9 image: the top three rows one colour (the north cap of a sphere), the bottom
/// three another, and distinct colours between, so a swapped axis or flipped row shows.
Vec3 texel(int i, int j) {
    if (j < 3) return Vec3(0.9, 0.2, 0.1);
    if (j >= kH - 3) return Vec3(0.1, 0.3, 0.8);
    return Vec3((i + 0.5) / kW, (j - 2.5) / 3.0, double((i + j) % 2));
}

/// The linear value after an 8-bit sRGB PNG.
Vec3 quantised(const Vec3& v) {
    Vec3 q;
    for (int c = 0; c < 3; ++c) q[c] = srgbDecode(srgbByte(float(v[c])) / 255.0);
    return q;
}

struct TextureFile {
    std::filesystem::path folder;
    std::shared_ptr<const Texture> texture;
    TextureFile(const std::string& name, const Image& image) {
        std::string pattern = (std::filesystem::temp_directory_path() / "kerf-tex-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        folder = pattern;
        writeImage(image, (folder / name).string());
        texture = Texture::open((folder / name).string());
    }
    ~TextureFile() { std::filesystem::remove_all(folder); }
};

Image distinctImage() {
    Image image(kW, kH, 3);
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i)
            for (int c = 0; c < 3; ++c) image.at(i, j, c) = float(texel(i, j)[c]);
    return image;
}

std::shared_ptr<Pattern> imagePattern(const std::shared_ptr<const Texture>& texture,
                                      ImageMap::Mapping mapping, Affine toPattern = {}) {
    auto map = std::make_shared<ImageMap>();
    map->mapping = mapping;
    map->texture = texture;
    auto p = std::make_shared<Pattern>();
    p->kind = Pattern::Kind::Image;
    p->image = map;
    p->toPattern = toPattern;
    return p;
}

/// u and v of texel (i, j)'s centre: v runs up the image.
double uOf(int i) { return (i + 0.5) / kW; }
double vOf(int j) { return 1.0 - (j + 0.5) / kH; }

void checkColour(const Vec3& got, const Vec3& want) {
    INFO("got " << got.x << ", " << got.y << ", " << got.z << "; want " << want.x << ", " << want.y
                << ", " << want.z);
    CHECK(glm::length(got - want) < 1e-4);
}

}  // namespace

TEST_CASE("image textures: planar and cylindrical maps put each texel at its point") {
    TextureFile file("distinct.png", distinctImage());
    // Planar, repeating, under the pattern's own scale 2 (the map into its space halves).
    const auto planar =
        imagePattern(file.texture, ImageMap::Mapping::Planar, Affine::scale(Vec3(0.5)));
    const auto cylinder = imagePattern(file.texture, ImageMap::Mapping::Cylindrical);
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            INFO("texel " << i << ", " << j);
            const Vec3 want = quantised(texel(i, j));
            checkColour(
                patternColor(*planar, Vec3(2.0 * (uOf(i) + 3.0), 2.0 * (vOf(j) - 1.0), 7.0), 0.0),
                want);
            // Cylindrical: the angle from +z toward +x in turns, v = y (repeating).
            const double angle = 2.0 * glm::pi<double>() * uOf(i);
            const double radius = 0.3 + i;
            checkColour(
                patternColor(*cylinder,
                             Vec3(radius * std::sin(angle), vOf(j) + 2.0, radius * std::cos(angle)),
                             0.0),
                want);
        }
}

TEST_CASE(
    "image textures: a spherical map puts the poles on the top and bottom rows, the equator in the "
    "middle") {
    TextureFile file("distinct.png", distinctImage());
    const auto sphere =
        imagePattern(file.texture, ImageMap::Mapping::Spherical,
                     Affine::translate(Vec3(-1.0, 2.0, 0.5)));  // centred at (1, −2, −½)
    const Vec3 centre(1.0, -2.0, -0.5);
    const double r = 3.0;
    checkColour(patternColor(*sphere, centre + Vec3(0.0, r, 0.0), 0.0), quantised(texel(0, 0)));
    checkColour(patternColor(*sphere, centre - Vec3(0.0, r, 0.0), 0.0),
                quantised(texel(0, kH - 1)));
    for (int j = 3; j < kH - 3; ++j)
        for (int i = 0; i < kW; ++i) {
            INFO("texel " << i << ", " << j);
            const double longitude = 2.0 * glm::pi<double>() * uOf(i);
            const double latitude = (vOf(j) - 0.5) * glm::pi<double>();  // 0 on row 4, the equator
            const Vec3 d(std::sin(longitude) * std::cos(latitude), std::sin(latitude),
                         std::cos(longitude) * std::cos(latitude));
            checkColour(patternColor(*sphere, centre + r * d, 0.0), quantised(texel(i, j)));
        }
}

TEST_CASE("image textures: a box map shows each face by the dominant axis of the normal") {
    TextureFile file("distinct.png", distinctImage());
    const auto box = imagePattern(file.texture, ImageMap::Mapping::Box);
    // Face by face, a point on it whose (u, v) is texel (i, j)'s centre, by the documented
    // formulas: +x (−z, y), −x (z, y), +y (x, −z), −y (x, z), +z (x, y), −z (−x, y).
    const int i = 5, j = 4;
    const double u = uOf(i) + 2.0, v = vOf(j) - 1.0;  // one period off: repeating
    struct Face {
        Vec3 normal, point;
    };
    const Face faces[] = {
        {Vec3(1, 0, 0), Vec3(0.7, v, -u)}, {Vec3(-1, 0, 0), Vec3(-0.7, v, u)},
        {Vec3(0, 1, 0), Vec3(u, 0.7, -v)}, {Vec3(0, -1, 0), Vec3(u, -0.7, v)},
        {Vec3(0, 0, 1), Vec3(u, v, 0.7)},  {Vec3(0, 0, -1), Vec3(-u, v, -0.7)},
    };
    for (const Face& f : faces) {
        INFO("face " << f.normal.x << ", " << f.normal.y << ", " << f.normal.z);
        // Tilted off the axis (but still dominant), as a curved surface's normal is.
        const Vec3 n =
            glm::normalize(f.normal + Vec3(0.2, -0.3, 0.25) * (1.0 - glm::abs(f.normal)));
        checkColour(patternColor(*box, f.point, 0.0, Footprint{Vec3(0.0), Vec3(0.0), n}),
                    quantised(texel(i, j)));
    }
    // The normal goes into the pattern's space: turned 90° about y, the world's +x face
    // shows the pattern's +z face (u = x, v = y in the pattern's space).
    const Affine turn = Affine::rotateDegrees(Vec3(0.0, 90.0, 0.0));
    const auto turned = imagePattern(file.texture, ImageMap::Mapping::Box, turn.inverse());
    const Vec3 q(uOf(i), vOf(j), 0.7);  // on the pattern's +z face
    checkColour(patternColor(*turned, turn.point(q), 0.0,
                             Footprint{Vec3(0.0), Vec3(0.0), turn.vector(Vec3(0, 0, 1))}),
                quantised(texel(i, j)));
}

TEST_CASE(
    "an image checkerboard on a floor to the horizon does not alias at one sample per pixel") {
    // The procedural checker's test (pattern_test.cpp) with the checker as an image: 64 × 64
    // texels of 2 × 2 cells, mapped planar across the floor with cells one unit wide. The far
    // band of a 1-sample render must have about the high-frequency energy of a 256-sample
    // reference and its grey within 0.05 on average; point sampling gives noise there.
    Image checker(64, 64, 1);
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) checker.at(i, j, 0) = float((i / 32 + j / 32) % 2);
    TextureFile file("checker.png", checker);
    const double m[12] = {0.5, 0, 0, 0, 0, 0, 0.5, 0, 0, 0.5, 0, 0};  // (x, z) / 2 → (u, v)
    Scene scene;
    Material floor = blackMaterial();
    floor.ambient = 1.0;
    floor.pattern = imagePattern(file.texture, ImageMap::Mapping::Planar, Affine::fromRowMajor(m));
    const int32_t material = addMaterial(scene, floor);
    addObject(scene, makeHalfSpace(Vec3(0.0, 1.0, 0.0), 0.0), material);
    scene.camera.eye = Vec3(0.0, 2.0, 0.0);
    scene.camera.lookAt = Vec3(0.3, 1.6, 10.0);
    scene.camera.fovDegrees = 50.0;
    RenderOptions options = smallImage(96, 72, 2);
    const RenderResult one = render(scene, options);
    options.spp = 256;
    const RenderResult reference = render(scene, options);
    const Camera camera(scene.camera, 96, 72);
    double energyOne = 0, energyRef = 0, diff = 0;
    int n = 0, near = 0;
    for (int j = 0; j < 72; ++j) {
        const Ray r = camera.rayThrough(48.0, j + 0.5);
        if (!(r.dir.y < 0.0)) continue;
        const double distance = -r.origin.y / r.dir.y;
        if (distance < 8.0) {  // near: whole cells, black or white where not on an edge
            for (int i = 0; i < 96; ++i)
                near += one.color.at(i, j, 0) < 0.02 || one.color.at(i, j, 0) > 0.98;
            continue;
        }
        if (distance < 40.0) continue;  // the far band: cells smaller than a pixel
        for (int i = 0; i + 1 < 96; ++i) {
            energyOne += std::pow(one.color.at(i + 1, j, 0) - one.color.at(i, j, 0), 2);
            energyRef += std::pow(reference.color.at(i + 1, j, 0) - reference.color.at(i, j, 0), 2);
            diff += std::fabs(one.color.at(i, j, 0) - reference.color.at(i, j, 0));
            ++n;
        }
    }
    REQUIRE(n > 200);
    INFO("energy 1 spp " << energyOne / n << ", reference " << energyRef / n << ", mean |diff| "
                         << diff / n << ", near pixels black or white " << near);
    CHECK(near > 500);  // the texture is there and sharp where it is big
    CHECK(energyOne / n <= 2.0 * energyRef / n + 1e-3);
    CHECK(diff / n < 0.05);
}
