// `pattern image { file … mapping … }`: lowered to an image pattern with its texture opened
// (relative to the model's folder), its mapping and transforms; and its mistakes, each one
// error at its own position.
#include "io/image.h"
#include "io/texture.h"
#include "lang_test_util.h"

#include <filesystem>

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

namespace {

/// A folder with models/tex/grey.png (4 × 2 texels), removed at the end.
struct ModelFolder {
    fs::path root;
    ModelFolder() {
        std::string pattern = (fs::temp_directory_path() / "kerf-lang-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        root = pattern;
        fs::create_directories(root / "models" / "tex");
        writeImage(Image(4, 2, 1), (root / "models" / "tex" / "grey.png").string());
    }
    ~ModelFolder() { fs::remove_all(root); }
    std::string model() const { return (root / "models" / "scene.kerf").string(); }
};

}  // namespace

TEST_CASE("image patterns: file relative to the model, mapping, transforms, bump and nesting") {
    ModelFolder folder;
    const Compiled c = compileText(R"(let t = "tex/grey.png";
material a { pattern image { file "tex/grey.png" mapping spherical } scale 2 }
material b { pattern checker { b pattern image { file t } } bump image { file t mapping box } }
object sphere { radius 1 } material a;
object sphere { center <3, 0, 0> radius 1 } material b;
)",
                                   folder.model());
    INFO(c.sink.format());
    REQUIRE(c.scene);
    const Pattern& a = *c.scene->materials[1].pattern;
    REQUIRE(a.kind == Pattern::Kind::Image);
    REQUIRE(a.image);
    CHECK(a.image->mapping == ImageMap::Mapping::Spherical);
    CHECK(a.image->path == (folder.root / "models" / "tex" / "grey.png").string());
    REQUIRE(a.image->texture);
    CHECK(a.image->texture->width() == 4);
    CHECK(a.image->texture->height() == 2);
    CHECK(a.toPattern.point(Vec3(2.0, 4.0, 6.0)) == Vec3(1.0, 2.0, 3.0));
    const Material& b = c.scene->materials[2];
    REQUIRE(b.pattern->b.pattern);
    CHECK(b.pattern->b.pattern->image->mapping == ImageMap::Mapping::Planar);  // the default
    REQUIRE(b.bump);
    CHECK(b.bump->image->mapping == ImageMap::Mapping::Box);
}

TEST_CASE("image patterns: mistakes are errors at their positions") {
    ModelFolder folder;
    const auto oneError = [&](const std::string& text, int line, int col,
                              const std::string& message) {
        const Compiled c = compileText(text, folder.model());
        INFO(c.sink.format());
        REQUIRE_FALSE(c.scene);
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics().front();
        CHECK_THAT(d.message, Catch::Matchers::Contains(message));
        CHECK(d.loc.line == line);
        CHECK(d.loc.col == col);
    };
    oneError("material m { pattern image { file \"tex/none.png\" } }\n", 1, 35,
             "cannot read texture 'tex/none.png': no such file");
    oneError("material m { pattern image { file \"tex\" } }\n", 1, 35, "it is a folder");
    oneError("material m { pattern image { file 3 } }\n", 1, 35,
             "expects a file name in quotes, got a number");
    oneError("material m { pattern image { file \"tex/grey.png\" mapping round } }\n", 1, 58,
             "unknown mapping 'round'");
    oneError("material m { pattern image { file \"tex/grey.png\" a <1, 0, 0> } }\n", 1, 50,
             "unknown property 'a'");
    oneError("material m { pattern image { mapping box } }\n", 1, 22, "needs the property 'file'");
}
