// The bit-step rounding of csg/interval/interval_round.h against nextafter, on every kind of
// double.
#include "csg/interval/interval_round.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>

using namespace kerf::interval_kernel;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void checkStep(double v, int& failures) {
    const double inf = std::numeric_limits<double>::infinity();
    const double d = down(v), u = up(v);
    const double ed = std::nextafter(v, -inf), eu = std::nextafter(v, inf);
    const bool ok =
        std::isnan(v) ? (std::isnan(d) && std::isnan(u)) : (sameBits(d, ed) && sameBits(u, eu));
    if (ok) return;
    std::ostringstream msg;
    msg.precision(17);
    msg << "down/up(" << v << ") = " << d << ", " << u << "; nextafter gives " << ed << ", " << eu;
    FAIL_CHECK(msg.str());
    ++failures;
}

}  // namespace

TEST_CASE("interval_kernel::down and up are nextafter towards -inf and +inf") {
    const double inf = std::numeric_limits<double>::infinity();
    const double dmin = std::numeric_limits<double>::denorm_min();
    const double nmin = std::numeric_limits<double>::min();
    const double dmax = std::numeric_limits<double>::max();
    int failures = 0;
    for (double v : {0.0, -0.0, dmin, -dmin, nmin, -nmin, dmax, -dmax, inf, -inf, 1.0, -1.0, 0.5,
                     2.0, -2.0, std::nan("")})
        checkStep(v, failures);
    std::mt19937_64 rng(17);
    for (int i = 0; i < 200000 && failures < 10; ++i) {
        // Random bit patterns: every exponent, subnormals, both signs.
        double v;
        const uint64_t b = rng();
        std::memcpy(&v, &b, sizeof v);
        checkStep(v, failures);
    }
    CHECK(failures == 0);
}
