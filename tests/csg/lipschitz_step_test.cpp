// The certified step of root isolation (csg/primitives/lipschitz_step.h): its reach against closed
// forms, the same crossings as plain bisection on polynomials with known roots (simple, close,
// double, tiny and huge scales, a root by the end of the range) and on random tapes along
// random rays, and no root skipped against a dense long-double scan of f along the ray.
#include "csg/primitives/lipschitz_step.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "csg/primitives/root_isolation.h"
#include "csg/tape/tape_along_ray.h"

using namespace kerf;

namespace {

/// p(t) = s·Π (t − rᵢ), enclosures by the product form and the product rule; enclosures at
/// points are the same form over [t, t] (rigorous, as certified steps need).
struct RootProduct {
    std::vector<double> roots;
    bool certifiedSteps = true;
    double scale = 1.0;
    double minCertifiedShrink = 1.0;

    void range(double a, double b, Interval& f, Interval& dfdt) const {
        const Interval t(a, b);
        f = Interval(scale);
        dfdt = Interval(0.0);
        for (double r : roots) {
            const Interval factor = t - Interval(r);
            dfdt = dfdt * factor + f;
            f = f * factor;
        }
    }
    double value(double t) const {
        double f = scale;
        for (double r : roots) f *= t - r;
        return f;
    }
    double valueAndSlope(double t, double& dfdt) const {
        double f = scale;
        dfdt = 0.0;
        for (double r : roots) {
            dfdt = dfdt * (t - r) + f;
            f *= t - r;
        }
        return f;
    }
    void enclosuresAt(const double* t, int n, Interval* f) const {
        Interval unused;
        for (int k = 0; k < n; ++k) range(t[k], t[k], f[k], unused);
    }
};

/// The same polynomial expanded, Σ cₖ tᵏ, with enclosures by Horner's rule on intervals: the
/// dependency problem widens them as a tape's are, so the certified steps find work.
struct Expanded {
    std::vector<double> c;  ///< c[k] multiplies tᵏ
    bool certifiedSteps = true;
    double minCertifiedShrink = 1.0;

    explicit Expanded(const std::vector<double>& roots) : c{1.0} {
        for (double r : roots) {  // multiply by (t − r)
            c.push_back(0.0);
            for (size_t k = c.size() - 1; k > 0; --k) c[k] = c[k - 1] - r * c[k];
            c[0] *= -r;
        }
    }
    template <typename T>
    T horner(const T& t, T& dfdt) const {
        T f = T(c.back());
        dfdt = T(0.0);
        for (size_t k = c.size() - 1; k-- > 0;) {
            dfdt = dfdt * t + f;
            f = f * t + T(c[k]);
        }
        return f;
    }
    void range(double a, double b, Interval& f, Interval& dfdt) const {
        f = horner(Interval(a, b), dfdt);
    }
    double value(double t) const {
        double unused;
        return horner(t, unused);
    }
    double valueAndSlope(double t, double& dfdt) const { return horner(t, dfdt); }
    void enclosuresAt(const double* t, int n, Interval* f) const {
        Interval unused;
        for (int k = 0; k < n; ++k) f[k] = horner(Interval(t[k]), unused);
    }
};

struct Crossing {
    double t;
    bool entering;
};

/// Both settings of the certified steps: only those that clear a whole piece (the default),
/// and partial ones too (a shrink by a quarter of the piece or more).
const double kMinShrinks[] = {1.0, 0.25};

template <typename P>
std::vector<Crossing> crossings(P p, double a, double b, double relTolerance, bool steps,
                                double minShrink, TraceStats* stats = nullptr) {
    TraceContext ctx;
    ctx.relTolerance = relTolerance;
    p.certifiedSteps = steps;
    p.minCertifiedShrink = minShrink;
    std::vector<Crossing> out;
    isolateRoots(p, a, b, 0.0, ctx, [&](double t, bool entering) { out.push_back({t, entering}); });
    if (stats) *stats = ctx.stats;
    return out;
}

std::string describe(const std::vector<Crossing>& c) {
    std::ostringstream s;
    s.precision(17);
    for (const Crossing& x : c) s << (x.entering ? " in@" : " out@") << x.t;
    return s.str();
}

/// c without pairs of crossings closer than 4× the tolerance: a touch (double root, grazing
/// ray) makes no crossing or such a pair, depending on where the search evaluated f, and
/// spans() drops what it makes.
std::vector<Crossing> withoutTouches(const std::vector<Crossing>& c, double relTolerance) {
    auto close = [&](size_t i) {
        return c[i + 1].t - c[i].t <= 4.0 * relTolerance * std::fabs(c[i + 1].t);
    };
    std::vector<Crossing> out;
    for (size_t i = 0; i < c.size(); ++i) {
        if (i + 1 < c.size() && close(i)) {
            ++i;  // skip the pair
            continue;
        }
        out.push_back(c[i]);
    }
    return out;
}

/// The same crossings (touches aside), each within the tolerance (relative to t, plus
/// `absolute`).
void checkSame(const std::vector<Crossing>& bisectedAll, const std::vector<Crossing>& steppedAll,
               double relTolerance, double absolute = 0.0) {
    INFO("bisection:" << describe(bisectedAll) << "\nstepping: " << describe(steppedAll));
    const auto bisected = withoutTouches(bisectedAll, relTolerance);
    const auto stepped = withoutTouches(steppedAll, relTolerance);
    REQUIRE(bisected.size() == stepped.size());
    for (size_t i = 0; i < bisected.size(); ++i) {
        CHECK(bisected[i].entering == stepped[i].entering);
        CHECK(std::fabs(bisected[i].t - stepped[i].t) <=
              2.0 * relTolerance * std::fabs(bisected[i].t) + absolute);
    }
}

}  // namespace

TEST_CASE("lipschitzStep/certifiedReach") {
    SECTION("a linear function: the reach is the distance to its root, never more") {
        // f(t) = 3 − 2t from t = 0: the root is at 1.5.
        CHECK(certifiedReach(3.0, Interval(-2.0), true) == Approx(1.5).epsilon(1e-15));
        CHECK(certifiedReach(3.0, Interval(-2.0), true) <= 1.5);
        // Inside, f(t) = −3 + 2t: the same.
        CHECK(certifiedReach(-3.0, Interval(2.0), true) <= 1.5);
        // Backward from b with f(b) = 3 and slope 2: f(b − s) = 3 − 2s.
        CHECK(certifiedReach(3.0, Interval(2.0), false) <= 1.5);
    }
    SECTION("the one-sided slope bound is used: a slope away from 0 never reaches it") {
        CHECK(std::isinf(certifiedReach(1.0, Interval(0.5, 7.0), true)));
        CHECK(certifiedReach(1.0, Interval(-4.0, 7.0), true) <= 0.25);
    }
    SECTION("no step without a certified sign or a bounded slope") {
        CHECK(certifiedReach(0.0, Interval(-1.0, 1.0), true) == 0.0);
        CHECK(certifiedReach(1.0, Interval::entire(), true) == 0.0);
        CHECK(certifiedReach(1.0, Interval(-1.0, 1.0, true), true) == 0.0);
        CHECK(certifiedMargin(Interval(-1e-300, 1e-300)) == 0.0);
        CHECK(certifiedMargin(Interval(1.0, 2.0, true)) == 0.0);
        CHECK(certifiedMargin(Interval(-2.0, -1.0)) == -1.0);
    }
}

TEST_CASE("lipschitzStep/same roots as bisection") {
    const double tol = 1e-9;
    struct Case {
        const char* name;
        std::vector<double> roots;
        double a, b;
        /// Expanded, the roots stay well conditioned (not a double or triple root, a pair
        /// 1e-12 apart or roots far from 0, where the expanded form's values are rounding).
        bool expandable;
    };
    const std::vector<Case> cases = {
        {"simple roots", {1.0, 2.0, 3.0}, 0.0, 4.0, true},
        {"roots 1e-6 apart", {1.0, 1.0 + 1e-6, 2.5}, 0.0, 4.0, true},
        {"a double root (tangent ray) before a simple one", {1.0, 1.0, 3.0}, 0.0, 4.0, false},
        {"a triple root", {2.0, 2.0, 2.0}, 0.0, 4.0, false},
        {"a root by the end of the range", {0.5, 4.0 - 1e-10}, 0.0, 4.0, true},
        {"a root by the start of the range", {1e-12, 3.0}, 0.0, 4.0, true},
        {"a grazing pair (a chord shorter than the tolerance)",
         {2.0, 2.0 + 1e-12},
         0.0,
         4.0,
         false},
        {"tiny scale", {1e-7, 1.5e-7, 3e-7}, 0.0, 4e-7, true},
        {"huge scale", {1e7, 1.5e7, 3e7}, 0.0, 4e7, true},
        {"far from the origin", {1e6 + 0.25, 1e6 + 0.5}, 1e6, 1e6 + 1.0, false},
        {"many roots", {0.1, 0.3, 0.35, 0.9, 1.7, 2.2, 2.21, 3.9}, 0.0, 4.0, true},
    };
    for (const Case& c : cases) {
        for (double scale : {1.0, -1.0, 1e-200, 1e200}) {
            for (double minShrink : kMinShrinks) {
                INFO(c.name << ", scale " << scale << ", minimum shrink " << minShrink);
                RootProduct p{c.roots, true, scale};
                const auto stepped = crossings(p, c.a, c.b, tol, true, minShrink);
                const auto bisected = crossings(p, c.a, c.b, tol, false, minShrink);
                checkSame(bisected, stepped, tol, 1e-300);
            }
        }
        for (double minShrink : kMinShrinks) {
            if (!c.expandable) break;
            INFO(c.name << ", expanded, minimum shrink " << minShrink);
            const Expanded e(c.roots);
            checkSame(crossings(e, c.a, c.b, tol, false, minShrink),
                      crossings(e, c.a, c.b, tol, true, minShrink), tol, 1e-300);
        }
    }
}

TEST_CASE("lipschitzStep/random polynomials") {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    const double tol = 1e-9;
    for (double minShrink : kMinShrinks) {
        int changed = 0;
        for (int trial = 0; trial < 400; ++trial) {
            RootProduct p;
            const int n = std::uniform_int_distribution<int>(1, 7)(rng);
            for (int i = 0; i < n; ++i) p.roots.push_back(u(rng));
            INFO("trial " << trial << ", minimum shrink " << minShrink);
            checkSame(crossings(p, 0.0, 10.0, tol, false, minShrink),
                      crossings(p, 0.0, 10.0, tol, true, minShrink), tol);
            // Expanded, the roots move by rounding: compare with bisection on the same form
            // (up to four roots: beyond, the values near the roots are rounding noise, which
            // both searches bisect down to the tolerance, slowly).
            if (n > 4) continue;
            const Expanded e(p.roots);
            TraceStats on, off;
            const auto withSteps = crossings(e, 0.0, 10.0, tol, true, minShrink, &on);
            const auto without = crossings(e, 0.0, 10.0, tol, false, minShrink, &off);
            checkSame(without, withSteps, tol);
            changed += on.rootSteps != off.rootSteps;
        }
        CHECK(changed > 20);  // the steps did change the search on many of them
    }
}

namespace {

using LVec = glm::tvec3<long double>;

/// Every interval [tᵢ, tᵢ₊₁] of a dense scan of f along the ray in long double where f changes
/// sign between samples whose |f| is above `floor` (below it the sign is rounding).
std::vector<std::pair<double, double>> scanSignChanges(const Tape& tape, const Ray& ray, double a,
                                                       double b, int samples, long double floor) {
    std::vector<std::pair<double, double>> out;
    const LVec o(ray.origin), d(ray.dir);
    long double prevT = a, prevF = tape.evalExtended(o + (long double)a * d);
    for (int i = 1; i <= samples; ++i) {
        const long double t = a + (b - a) * (long double)i / samples;
        const long double f = tape.evalExtended(o + t * d);
        if (std::fabs(f) > floor) {
            if (std::fabs(prevF) > floor && (f > 0) != (prevF > 0))
                out.push_back({(double)prevT, (double)t});
            prevT = t, prevF = f;
        }
    }
    return out;
}

std::shared_ptr<const Tape> compile(ExprGraph& g, ExprId root) { return Tape::compile(g, root); }

std::shared_ptr<const Tape> gyroid(double period) {
    ExprGraph g;
    const ExprId k = g.constant(2.0 * M_PI / period);
    const ExprId u = g.binary(Op::Mul, k, g.x()), v = g.binary(Op::Mul, k, g.y()),
                 w = g.binary(Op::Mul, k, g.z());
    auto term = [&](ExprId a, ExprId b) {
        return g.binary(Op::Mul, g.unary(Op::Sin, a), g.unary(Op::Cos, b));
    };
    return compile(g, g.binary(Op::Add, g.binary(Op::Add, term(u, v), term(v, w)), term(w, u)));
}

std::shared_ptr<const Tape> sphere(double radius) {
    ExprGraph g;
    const ExprId r2 =
        g.binary(Op::Add, g.binary(Op::Add, g.unary(Op::Square, g.x()), g.unary(Op::Square, g.y())),
                 g.unary(Op::Square, g.z()));
    return compile(g, g.binary(Op::Sub, r2, g.constant(radius * radius)));
}

/// Barth's sextic, as bench/gen_implicit_scenes.py writes it.
std::shared_ptr<const Tape> barth() {
    ExprGraph g;
    const double phi2 = 2.618033988749895;
    auto sq = [&](ExprId a) { return g.unary(Op::Square, a); };
    auto mul = [&](ExprId a, ExprId b) { return g.binary(Op::Mul, a, b); };
    auto sub = [&](ExprId a, ExprId b) { return g.binary(Op::Sub, a, b); };
    const ExprId x2 = sq(g.x()), y2 = sq(g.y()), z2 = sq(g.z());
    const ExprId r = sub(g.binary(Op::Add, g.binary(Op::Add, x2, y2), z2), g.constant(1.0));
    const ExprId k = g.constant(phi2);
    const ExprId prod = mul(mul(sub(mul(k, x2), y2), sub(mul(k, y2), z2)), sub(mul(k, z2), x2));
    return compile(g, sub(mul(g.constant(4.23606797749979), sq(r)), mul(g.constant(4.0), prod)));
}

Vec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    const Vec3 v(n(rng), n(rng), n(rng));
    return v / glm::length(v);
}

}  // namespace

TEST_CASE("lipschitzStep/no root skipped against a dense scan") {
    struct Shape {
        const char* name;
        std::shared_ptr<const Tape> tape;
        double size;  ///< rays pass within this of the origin, over t in [0, 4·size]
    };
    const std::vector<Shape> shapes = {
        {"gyroid", gyroid(1.0), 2.0},
        {"gyroid, scaled by 1e-6", gyroid(1e-6), 2e-6},
        {"gyroid, scaled by 1e6", gyroid(1e6), 2e6},
        {"sphere", sphere(1.0), 1.0},
        {"barth", barth(), 1.8},
    };
    std::mt19937_64 rng(88);
    const double tol = 1e-9;
    for (const Shape& s : shapes) {
        for (int trial = 0; trial < 40; ++trial) {
            Ray ray;
            ray.dir = randomUnit(rng);
            // Start 2·size back along the ray from a random point near the origin; a few rays
            // graze the sphere (pass at distance 1 − 1e-9 from its centre).
            Vec3 through = randomUnit(rng) * (s.size * 0.5);
            if (trial % 8 == 0 && std::string(s.name) == "sphere") {
                const Vec3 side = glm::normalize(glm::cross(ray.dir, Vec3(0.3, 0.5, 0.7)));
                through = side * (1.0 - 1e-9);
            }
            ray.origin = through - 2.0 * s.size * ray.dir;
            const double a = 0.0, b = 4.0 * s.size;
            INFO(s.name << ", trial " << trial);
            TapeAlongRay p{*s.tape, ray};
            const auto bisected = crossings(p, a, b, tol, false, 1.0);
            for (double minShrink : kMinShrinks) {
                INFO("minimum shrink " << minShrink);
                checkSame(bisected, crossings(p, a, b, tol, true, minShrink), tol, 1e-300);
            }
            const auto stepped = crossings(p, a, b, tol, true, p.minCertifiedShrink);
            // Every sign change the dense scan sees holds a crossing of the stepped search.
            const long double floor = 1e-12L;
            const auto changes = scanSignChanges(*s.tape, ray, a, b, 20000, floor);
            for (const auto& [lo, hi] : changes) {
                const double slack = 2.0 * tol * hi;
                bool found = false;
                for (const Crossing& c : stepped) found |= c.t >= lo - slack && c.t <= hi + slack;
                INFO("a sign change in [" << lo << ", " << hi << "]: " << describe(stepped));
                CHECK(found);
            }
        }
    }
}

namespace {

/// A random expression DAG of `size` nodes over x, y, z and constants, with the ops of the lean
/// along-ray path. (No division: near a pole the search bisects to the tolerance with or
/// without steps, too slowly for a test; certifiedReach's own test covers unbounded slopes.)
std::shared_ptr<const Tape> randomTape(std::mt19937_64& rng, int size) {
    const Op ops[] = {Op::Add, Op::Sub, Op::Mul, Op::Neg, Op::Square, Op::Sin, Op::Cos};
    ExprGraph g;
    std::vector<ExprId> nodes = {g.x(), g.y(), g.z()};
    std::uniform_real_distribution<double> constant(-2.0, 2.0);
    for (int i = 0; i < 2; ++i) nodes.push_back(g.constant(constant(rng)));
    for (int i = 0; i < size; ++i) {
        const Op op = ops[std::uniform_int_distribution<int>(0, 6)(rng)];
        auto pick = [&] {
            const size_t n = nodes.size();
            const size_t back = std::geometric_distribution<size_t>(0.3)(rng);
            return nodes[n - 1 - std::min<size_t>(n - 1, back)];
        };
        const bool binary = op == Op::Add || op == Op::Sub || op == Op::Mul;
        nodes.push_back(binary ? g.binary(op, pick(), pick()) : g.unary(op, pick()));
    }
    return Tape::compile(g, nodes.back());
}

}  // namespace

TEST_CASE("lipschitzStep/random tapes along random rays") {
    std::mt19937_64 rng(808);
    // A loose tolerance: a random tape can be flat at 0 over a stretch (x − x), which both
    // searches bisect down to the tolerance.
    const double tol = 1e-5;
    int compared = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const auto tape = randomTape(rng, 12);
        Ray ray;
        ray.dir = randomUnit(rng);
        ray.origin = randomUnit(rng) * 3.0;
        INFO("trial " << trial);
        TapeAlongRay p{*tape, ray};
        const auto bisected = crossings(p, 0.0, 6.0, tol, false, 1.0);
        if (bisected.size() > 40) continue;  // a tape gone wild (near a pole): rounding noise
        for (double minShrink : kMinShrinks) {
            INFO("minimum shrink " << minShrink);
            // The first crossing (what a camera ray keeps) and every later one agree.
            checkSame(bisected, crossings(p, 0.0, 6.0, tol, true, minShrink), tol, 1e-300);
        }
        ++compared;
    }
    CHECK(compared > 30);
}
