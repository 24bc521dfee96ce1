/// @file tests/util/compiled_scene.h
/// @brief A model compiled for a test that needs it to compile: the diagnostics are shown if it
/// does not.
#pragma once

#include "assets/asset_cache.h"
#include "lang/compile.h"

#include <catch2/catch.hpp>

#include <optional>
#include <string>

namespace kerf::test {

inline Scene compiledScene(const std::string& text, const std::string& name = "test.kerf") {
    DiagnosticSink sink;
    AssetCache assets;
    std::optional<Scene> scene = compileString(text, name, sink, assets);
    INFO(sink.format());
    REQUIRE(scene.has_value());
    return std::move(*scene);
}

inline Scene compiledSceneFile(const std::string& path) {
    DiagnosticSink sink;
    AssetCache assets;
    std::optional<Scene> scene = compileFile(path, sink, assets);
    INFO(path << "\n" << sink.format());
    REQUIRE(scene.has_value());
    return std::move(*scene);
}

}  // namespace kerf::test
