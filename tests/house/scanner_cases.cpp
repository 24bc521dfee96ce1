// Cases for the function-length scanner's self-test (never compiled): each function is preceded
// by "expect: NAME LINES", the lines strictly between its braces. Scopes, initializers and
// braced members in between must not be taken for functions. Kept as written, unformatted.
// clang-format off
#include <vector>
#define LONG_MACRO(x) \
    { x; }

namespace outer {
namespace {

struct Point {
    int x{0};
    int y = {1};
    // expect: norm 0
    int norm() const { return x + y; }
};

const int kTable[] = {1, 2, 3};

}  // namespace

// expect: braces 3
int braces(int a) {
    const char* s = "}}} { ";
    const char c = '}';
    /* } */ return a + s[0] + c;  // {
}

template <class T, typename U>
// expect: pick 2
T pick(T a, U b) {
    auto lambda = [&](int k) { return k + 1; };
    return a + lambda(b);
}

class Grid {
public:
    // expect: Grid 1
    Grid(int n) : mN(n), mCells{n, n} {
        mN += 1;
    }
    // expect: operator() 0
    int operator()(int k) const noexcept { return k; }
    // expect: size 0
    auto size() const -> int { return mN; }

private:
    int mN;
    std::vector<int> mCells;
};

// expect: Grid::raw 4
const char* Grid::raw() {
    return R"x(
} } {
)x";
    int big = 1'000;
}

}  // namespace outer

extern "C" {
// expect: cEntry 1
int cEntry(void) {
    return 0;
}
}
// clang-format on
