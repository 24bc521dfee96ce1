/// @file tests/mesh/mesh_error_check.h
/// @brief The loader tests' check of a refused file. Header-only because the test build
/// compiles only *_test.cpp files.
#pragma once

#include "mesh/mesh_loader.h"

#include <catch2/catch.hpp>

#include <string>

namespace kerf::test {

/// Expects loadMesh(path) to throw a MeshError whose message names the file and contains
/// `what` (empty: any reason, for errors Assimp itself words).
inline void requireMeshError(const std::string& path, const std::string& what) {
    try {
        loadMesh(path);
        FAIL("no MeshError for " << path);
    } catch (const MeshError& e) {
        const std::string message = e.what();
        INFO(message);
        CHECK(message.find(path) != std::string::npos);
        CHECK(message.find(what) != std::string::npos);
    }
}

}  // namespace kerf::test
