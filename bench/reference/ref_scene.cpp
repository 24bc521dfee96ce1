/// @file bench/reference/ref_scene.cpp
#include "ref_scene.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace kerf::bench {

namespace {

constexpr Real kPi = 3.141592653589793238462643383279502884L;

/// cos and sin of an angle in degrees; exact at multiples of 90 degrees.
void cosSinDegrees(Real degrees, Real& c, Real& s) {
    const Real quarter = degrees / 90;
    if (quarter == std::floor(quarter)) {
        const long k = ((static_cast<long>(quarter) % 4) + 4) % 4;
        const Real cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
        c = cs[k];
        s = sn[k];
        return;
    }
    const Real radians = degrees * (kPi / 180);
    c = std::cos(radians);
    s = std::sin(radians);
}

/// World from local of `rotate <x, y, z>`: about x, then y, then z (right-handed).
M3 rotation(V3 degrees) {
    Real c, s;
    M3 rx, ry, rz;
    cosSinDegrees(degrees.x, c, s);
    rx.m[1][1] = c, rx.m[1][2] = -s, rx.m[2][1] = s, rx.m[2][2] = c;
    cosSinDegrees(degrees.y, c, s);
    ry.m[0][0] = c, ry.m[0][2] = s, ry.m[2][0] = -s, ry.m[2][2] = c;
    cosSinDegrees(degrees.z, c, s);
    rz.m[0][0] = c, rz.m[0][1] = -s, rz.m[1][0] = s, rz.m[1][1] = c;
    return rz * ry * rx;
}

class Reader {
public:
    explicit Reader(const std::string& path) : mIn(path), mPath(path) {
        if (!mIn) throw std::runtime_error(path + ": cannot open");
    }

    /// The next non-empty, non-comment line as a word stream; false at the end of the file.
    bool next(std::istringstream& words, std::string& keyword) {
        std::string line;
        while (std::getline(mIn, line)) {
            ++mLine;
            if (line.empty() || line[0] == '#') continue;
            words.clear();
            words.str(line);
            words >> keyword;
            return true;
        }
        return false;
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw std::runtime_error(mPath + ":" + std::to_string(mLine) + ": " + message);
    }

    Real number(std::istringstream& words) {
        Real value;
        if (!(words >> value)) fail("expected a number");
        return value;
    }

    V3 vector(std::istringstream& words) {
        V3 v;
        v.x = number(words);
        v.y = number(words);
        v.z = number(words);
        return v;
    }

    RefNode node() {
        std::istringstream words;
        std::string keyword;
        if (!next(words, keyword)) fail("unexpected end of file: a node is missing");
        RefNode n;
        using K = RefNode::Kind;
        if (keyword == "sphere") {
            n.kind = K::Sphere, n.a = vector(words), n.r1 = number(words);
        } else if (keyword == "box") {
            n.kind = K::Box, n.a = vector(words), n.b = vector(words);
        } else if (keyword == "cylinder") {
            n.kind = K::Cylinder, n.a = vector(words), n.b = vector(words), n.r1 = number(words);
        } else if (keyword == "halfspace") {
            n.kind = K::HalfSpace, n.a = vector(words), n.r1 = number(words);
        } else if (keyword == "torus") {
            n.kind = K::Torus, n.r1 = number(words), n.r2 = number(words);
        } else if (keyword == "union" || keyword == "intersection" || keyword == "difference") {
            n.kind = keyword == "union"          ? K::Union
                     : keyword == "intersection" ? K::Intersection
                                                 : K::Difference;
            const Real count = number(words);
            if (count < 1) fail("a CSG node needs at least one child");
            for (long i = 0; i < static_cast<long>(count); ++i) n.children.push_back(node());
        } else if (keyword == "translate" || keyword == "rotate" || keyword == "scale") {
            n.kind = K::Transform;
            const V3 v = vector(words);
            if (keyword == "translate") {
                n.offset = v;
            } else if (keyword == "rotate") {
                n.localFromWorld = transpose(rotation(v));
            } else {
                if (v.x == 0 || v.y == 0 || v.z == 0) fail("zero scale");
                n.localFromWorld.m[0][0] = 1 / v.x;
                n.localFromWorld.m[1][1] = 1 / v.y;
                n.localFromWorld.m[2][2] = 1 / v.z;
            }
            n.children.push_back(node());
        } else {
            fail("unknown node '" + keyword + "'");
        }
        return n;
    }

    RefScene scene() {
        RefScene s;
        std::istringstream words;
        std::string keyword;
        bool haveCamera = false;
        while (next(words, keyword)) {
            if (keyword == "camera") {
                s.camera.eye = vector(words);
                s.camera.lookAt = vector(words);
                s.camera.up = vector(words);
                s.camera.fovDegrees = number(words);
                haveCamera = true;
            } else if (keyword == "object") {
                s.objects.push_back(node());
            } else {
                fail("expected 'camera' or 'object', got '" + keyword + "'");
            }
        }
        if (!haveCamera) fail("no camera");
        return s;
    }

private:
    std::ifstream mIn;
    std::string mPath;
    long mLine = 0;
};

}  // namespace

RefScene readRefScene(const std::string& path) { return Reader(path).scene(); }

}  // namespace kerf::bench
