/// @file tests/lang/lang_test_util.h
/// @brief Helpers for the lang tests: compile text and look at the diagnostics it produced.
#pragma once

#include "assets/asset_cache.h"
#include "lang/compile.h"

#include <catch2/catch.hpp>

#include <optional>
#include <string>

namespace kerf::test {

struct Compiled {
    DiagnosticSink sink;
    std::optional<Scene> scene;
};

inline Compiled compileText(const std::string& text, const std::string& name = "test.kerf") {
    Compiled c;
    AssetCache assets;  // a fresh cache: each test compile reads its files as before
    c.scene = compileString(text, name, c.sink, assets);
    return c;
}

/// The first object of a model that must compile.
inline NodePtr firstObject(const std::string& text) {
    const Compiled c = compileText(text);
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    REQUIRE(!c.scene->objects.empty());
    return c.scene->objects[0];
}

/// The compilation failed with exactly one error, at line:col, whose message contains `message`.
inline void requireOneError(const Compiled& c, int line, int col, const std::string& message) {
    INFO(c.sink.format());
    REQUIRE_FALSE(c.scene.has_value());
    REQUIRE(c.sink.errorCount() == 1);
    const Diagnostic& d = c.sink.diagnostics().front();
    CHECK_THAT(d.message, Catch::Matchers::Contains(message));
    CHECK(d.loc.line == line);
    CHECK(d.loc.col == col);
}

/// The text compiles with exactly one error, at line:col, whose message contains `message`.
inline void requireOneError(const std::string& text, int line, int col,
                            const std::string& message) {
    requireOneError(compileText(text), line, col, message);
}

}  // namespace kerf::test
