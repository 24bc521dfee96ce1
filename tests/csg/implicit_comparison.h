/// @file tests/csg/implicit_comparison.h
/// @brief For the tests of the profile solids traced in closed form (prism, lathe): their
/// spans against those of the implicit they stand for, found by root isolation.
#pragma once

#include <catch2/catch.hpp>
#include <iomanip>
#include <string>
#include <variant>
#include <vector>

#include "csg/trace_context.h"
#include "csg/tree/solids.h"
#include "csg/tree/span.h"

namespace kerf {
struct Traced {
    SpanList spans;
    TraceStats stats;
};

inline Traced traced(const NodePtr& node, const Ray& ray, double relTolerance = 1e-12) {
    Traced r;
    TraceContext ctx;
    ctx.relTolerance = relTolerance;
    node->spans(ray, -kInf, kInf, ctx, r.spans);
    r.stats = ctx.stats;
    return r;
}

/// The implicit a closed-form profile solid stands for: its own parameters rebuilt by makeImplicit.
inline NodePtr implicitOf(const NodePtr& node) {
    const auto p = std::get<ImplicitParams>(node->params());
    return makeImplicit(p.tape, p.bound);
}

/// `normals`: also compare the normals (not at a vertex, where the implicit's gradient picks
/// any side; the closed form's must still face out: against the ray entering, along leaving).
inline void requireSameSpans(const SpanList& exact, const SpanList& isolated, const Ray& ray,
                             bool normals = true) {
    INFO(std::setprecision(17) << "ray o=(" << ray.origin.x << "," << ray.origin.y << ","
                               << ray.origin.z << ") d=(" << ray.dir.x << "," << ray.dir.y << ","
                               << ray.dir.z << ")");
    // Spans and gaps thinner than the isolation's tolerance (a ray through or within rounding
    // of a vertex) may be kept by one and not the other: drop such spans, close such gaps.
    const auto normalised = [](const SpanList& in) {
        std::vector<Span> out;
        for (int i = 0; i < in.size(); ++i) {
            if (in[i].out.t - in[i].in.t <= 1e-9) continue;
            if (!out.empty() && in[i].in.t - out.back().out.t <= 1e-9) {
                out.back().out = in[i].out;
                continue;
            }
            out.push_back(in[i]);
        }
        return out;
    };
    const std::vector<Span> a = normalised(exact), b = normalised(isolated);
    const auto list = [](const std::vector<Span>& v) {
        std::string text;
        for (const Span& x : v)
            text += "[" + std::to_string(x.in.t) + ", " + std::to_string(x.out.t) + "] n=(" +
                    std::to_string(x.in.normal.x) + "," + std::to_string(x.in.normal.y) + "," +
                    std::to_string(x.in.normal.z) + ") ";
        return text;
    };
    INFO("closed form: " << list(a) << "\nisolated: " << list(b));
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].in.t == Approx(b[i].in.t).margin(1e-9));
        CHECK(a[i].out.t == Approx(b[i].out.t).margin(1e-9));
        CHECK(glm::dot(a[i].in.normal, ray.dir) < 0.0);
        CHECK(glm::dot(a[i].out.normal, ray.dir) > 0.0);
        if (!normals) continue;
        CHECK(glm::dot(a[i].in.normal, b[i].in.normal) > 0.999);
        CHECK(glm::dot(a[i].out.normal, b[i].out.normal) > 0.999);
    }
}

}  // namespace kerf
