/// @file tests/lang/openscad_test_util.h
/// @brief What the .csg reader's tests share: reading a text, and the spans of its one object.
#pragma once

#include "assets/asset_cache.h"
#include "csg/trace_context.h"
#include "csg/tree/span.h"
#include "lang/openscad_csg.h"

#include <catch2/catch.hpp>

#include <optional>
#include <string>

namespace kerf::test {

struct Read {
    DiagnosticSink sink;
    std::optional<Scene> scene;
};

inline Read readCsg(const std::string& text) {
    Read r;
    AssetCache assets;
    r.scene = compileOpenScadString(text, "test.csg", r.sink, assets);
    return r;
}

/// The spans of the scene's one object along a ray given in kerf's coordinates.
inline SpanList spansOf(const Read& r, const Vec3& origin, const Vec3& dir) {
    INFO(r.sink.format());
    REQUIRE(r.scene.has_value());
    REQUIRE(r.scene->objects.size() == 1);
    TraceContext ctx;
    SpanList spans;
    r.scene->objects[0]->spans(Ray{origin, dir}, 0, kInf, ctx, spans);
    return spans;
}

}  // namespace kerf::test
