// Parse memory per byte of model (issue 7, docs/robustness.md "Parse memory"): the heap the
// parser holds at its peak, counted by a replaced global operator new in this test binary
// (not RSS, which is noisy), must stay at most 10 bytes per byte of model text.
#include "lang/lexer.h"
#include "lang/lower.h"
#include "lang/parser.h"
#include "lang/source.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>

#include <malloc.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang's spelling of GCC's __SANITIZE_ADDRESS__
#define KERF_CLANG_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(KERF_CLANG_ASAN)
#define KERF_COUNTS_ALLOCATIONS 0  // AddressSanitizer owns the allocator; its sizes are not ours
#else
#define KERF_COUNTS_ALLOCATIONS 1
#endif

namespace {

#if KERF_COUNTS_ALLOCATIONS
// Live heap bytes as the allocator sees them: the usable size plus the chunk header.
std::atomic<long long> gLive{0};
std::atomic<long long> gPeak{0};

long long chunkBytes(void* p) {
    return static_cast<long long>(malloc_usable_size(p) + sizeof(size_t));
}

void* counted(size_t n) {
    void* p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    const long long live = gLive += chunkBytes(p);
    long long peak = gPeak.load();
    while (live > peak && !gPeak.compare_exchange_weak(peak, live)) {
    }
    return p;
}

void release(void* p) noexcept {
    if (!p) return;
    gLive -= chunkBytes(p);
    std::free(p);
}
#endif

}  // namespace

#if KERF_COUNTS_ALLOCATIONS
void* operator new(size_t n) { return counted(n); }
void* operator new[](size_t n) { return counted(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, size_t) noexcept { release(p); }
void operator delete[](void* p, size_t) noexcept { release(p); }
// The nothrow forms too (std::stable_sort's temporary buffer takes one): left to the runtime's,
// their blocks would come back through the replaced delete, a new/free mismatch under ASan.
void* operator new(size_t n, const std::nothrow_t&) noexcept {
    try {
        return counted(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](size_t n, const std::nothrow_t& tag) noexcept { return operator new(n, tag); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
#endif

using namespace kerf;

namespace {

/// Statement i of the model scripts/gen-parse-memory-model writes: a named box minus a
/// sphere, translated, with a material (17 expressions, about 170 bytes).
std::string statement(int i, double& radius) {
    const double a = 1 + (i % 97) / 97.0, b = 1 + (i % 89) / 89.0, c = 1 + (i % 83) / 83.0;
    radius = 0.5 + (i % 7) / 10.0;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "solid s%d = difference { box { min <%.2f, %.2f, %.2f> max <%.2f, %.2f, %.2f> } "
                  "sphere { center "
                  "<%.1f, %.1f, %.1f> radius %.1f } } translate <%.1f, %.1f, %.1f> material m;\n",
                  i, a, b, c, a + 1.5, b + 1.5, c + 1.5, a, b + 1.5, c, radius, (i % 1000) * 0.5,
                  (i / 1000 % 1000) * 0.5, (i / 1000000) * 0.5);
    return buf;
}

}  // namespace

TEST_CASE("parse memory: at most 10 bytes of heap per byte of model") {
#if KERF_COUNTS_ALLOCATIONS
    const int count = 20000;  // about 3.4 MB
#else
    const int count = 2000;  // the parse is still checked, only smaller
#endif
    std::string text = "material m { color <0.8, 0.6, 0.4> }\n";
    std::vector<double> radii(count);
    for (int i = 0; i < count; ++i) text += statement(i, radii[i]);
    const SourceText source{std::make_shared<const std::string>("big.kerf"),
                            std::make_shared<const std::string>(std::move(text))};
    const double bytes = static_cast<double>(source.text->size());

    DiagnosticSink sink;
    sink.rememberSource(source.name, source.text);
#if KERF_COUNTS_ALLOCATIONS
    const long long before = gLive.load();
    gPeak = before;
#endif
    TokenStream tokens(source, sink);
    const Program program = parse(tokens, sink);
#if KERF_COUNTS_ALLOCATIONS
    const double perByte = static_cast<double>(gPeak.load() - before) / bytes;
#endif

    INFO(sink.format());
    REQUIRE(sink.errorCount() == 0);
    REQUIRE(program.statements.size() == static_cast<size_t>(count) + 1);
    // The tree holds what was written: every sphere's radius, and the last name.
    for (int i = 0; i < count; ++i) {
        const Statement& s = program.statements[static_cast<size_t>(i) + 1];
        const Solid& sphere = s.solid->children.at(1);
        REQUIRE(sphere.properties.at(1).name == "radius");
        REQUIRE(std::fabs(sphere.properties[1].expr->number - radii[i]) <= 1e-12);
    }
    CHECK(program.statements.back().name == "s" + std::to_string(count - 1));

#if KERF_COUNTS_ALLOCATIONS
    INFO("peak heap of the parse: " << perByte << " bytes per byte of a " << bytes
                                    << "-byte model");
    CHECK(perByte <= 10.0);
    WARN("parse memory: " << perByte << " bytes of heap per byte of model");
#else
    WARN(
        "allocation count skipped under AddressSanitizer (its allocator replaces ours); parse "
        "checked on "
        << bytes << " bytes");
#endif
}

// The same measurement on a model file, for docs/robustness.md (hidden: run it by its tag):
//   scripts/gen-parse-memory-model -o /tmp/big.kerf
//   KERF_PARSE_MEMORY_MODEL=/tmp/big.kerf build/tests/kerf_lang_tests "[parse-memory]"
// Prints the parse's peak and that of parse + lowering (what `kerf check` holds above the text).
TEST_CASE("parse memory: a model file named by KERF_PARSE_MEMORY_MODEL", "[.][parse-memory]") {
    const char* path = std::getenv("KERF_PARSE_MEMORY_MODEL");
    if (!path) {
        WARN("KERF_PARSE_MEMORY_MODEL is not set: nothing measured");
        return;
    }
    std::string why;
    auto bytes = readFileBytes(path, why);
    INFO(why);
    REQUIRE(bytes);
    const SourceText source{std::make_shared<const std::string>(path),
                            std::make_shared<const std::string>(std::move(*bytes))};
    [[maybe_unused]] const double size = static_cast<double>(source.text->size());
    DiagnosticSink sink;
    sink.rememberSource(source.name, source.text);
#if KERF_COUNTS_ALLOCATIONS
    const long long before = gLive.load();
    gPeak = before;
#endif
    TokenStream tokens(source, sink);
    Program program = parse(tokens, sink);
#if KERF_COUNTS_ALLOCATIONS
    const double parsePeak = static_cast<double>(gPeak.load() - before) / size;
#endif
    const std::optional<Scene> scene = Lowering(sink).lower(program);
    INFO(sink.format());
    REQUIRE(scene.has_value());
#if KERF_COUNTS_ALLOCATIONS
    const double compilePeak = static_cast<double>(gPeak.load() - before) / size;
    WARN(path << ": " << size << " bytes, " << program.statements.size()
              << " statements; peak heap per byte of "
              << "model: parse " << parsePeak << ", parse + lowering " << compilePeak);
    CHECK(parsePeak <= 10.0);
#endif
}
