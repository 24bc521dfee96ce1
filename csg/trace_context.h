/// @file csg/trace_context.h
/// @brief Per-thread state for tracing: the tolerance in force, the statistics counters and
/// the reusable span storage.
#pragma once

#include "csg/tree/span.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kerf {

/// Counters kept per thread and summed at the end (`--stats`).
struct TraceStats {
    uint64_t primitiveTests = 0;  ///< calls of a primitive's span computation
    uint64_t boundsTests = 0;     ///< ray–box tests of node bounds and BVH nodes
    uint64_t rootSteps = 0;       ///< interval subdivisions and polish iterations
    uint64_t intervalEvals = 0;   ///< interval evaluations of implicit functions
    uint64_t cellsVisited = 0;    ///< octree cells and skipped blocks a ray walked through
    uint64_t meshNodes = 0;       ///< triangle-BVH nodes visited (mesh/triangle_bvh.h)
    uint64_t triangleTests = 0;   ///< ray–triangle tests

    TraceStats& operator+=(const TraceStats& o) {
        primitiveTests += o.primitiveTests;
        boundsTests += o.boundsTests;
        rootSteps += o.rootSteps;
        intervalEvals += o.intervalEvals;
        cellsVisited += o.cellsVisited;
        meshNodes += o.meshNodes;
        triangleTests += o.triangleTests;
        return *this;
    }
};

/// How primitives find where a ray crosses their surface.
enum class TraceMethod {
    /// Closed forms where a primitive has one (sphere, box, cylinder, cone, half-space),
    /// interval root isolation otherwise (torus, implicit). The default.
    Closed,
    /// Interval root isolation of every primitive's implicit form, closed forms unused.
    Interval,
    /// Sphere tracing of every primitive's implicit form with a Lipschitz bound. For the
    /// accuracy comparison only: it can step over thin features and grazing hits.
    SphereTrace,
};

/// "closed", "interval", "sphere-trace": the names the command line uses.
const char* traceMethodName(TraceMethod method);

/// The method named by traceMethodName, or nullopt.
std::optional<TraceMethod> parseTraceMethod(const std::string& name);

/// Span lists reused by nested span computations, in stack order: a Boolean node takes its
/// temporaries here instead of building fresh lists on every call, so after the first rays a
/// thread's trace allocates nothing. Copying a context copies none of it (it is scratch).
class SpanScratch {
public:
    SpanScratch() = default;
    SpanScratch(const SpanScratch&) {}
    SpanScratch& operator=(const SpanScratch&) { return *this; }

    /// The next free list (contents unspecified); release() gives back the latest one.
    SpanList& acquire() {
        if (mUsed == mLists.size()) mLists.push_back(std::make_unique<SpanList>());
        return *mLists[mUsed++];
    }
    void release() { --mUsed; }

private:
    std::vector<std::unique_ptr<SpanList>> mLists;  ///< stable addresses as the stack grows
    size_t mUsed = 0;
};

/// A scratch span list held for one scope.
class ScratchSpans {
public:
    explicit ScratchSpans(SpanScratch& scratch) : mScratch(scratch), mList(scratch.acquire()) {}
    ~ScratchSpans() { mScratch.release(); }
    ScratchSpans(const ScratchSpans&) = delete;
    ScratchSpans& operator=(const ScratchSpans&) = delete;
    SpanList& operator*() const { return mList; }
    SpanList* operator->() const { return &mList; }

private:
    SpanScratch& mScratch;
    SpanList& mList;
};

/// What a trace needs besides the ray. One per thread; never shared.
struct TraceContext {
    /// Hit distances must satisfy |t − t*| ≤ relTolerance·|t*|; spans thinner than
    /// relTolerance·|t| vanish. Closed-form primitives are exact to double precision anyway.
    double relTolerance = 1e-9;
    TraceMethod method = TraceMethod::Closed;
    /// The caller needs only where surfaces are, within the tolerance (shadow rays): root
    /// polishing may stop there instead of at double precision, and root-found boundaries
    /// may leave their normal unset (zero). Set for a scope by OcclusionScope.
    bool occlusionOnly = false;
    TraceStats stats;
    SpanScratch scratch;
};

/// Sets TraceContext::occlusionOnly for a scope (restoring the caller's value).
class OcclusionScope {
public:
    explicit OcclusionScope(TraceContext& ctx) : mCtx(ctx), mWas(ctx.occlusionOnly) {
        ctx.occlusionOnly = true;
    }
    ~OcclusionScope() { mCtx.occlusionOnly = mWas; }
    OcclusionScope(const OcclusionScope&) = delete;
    OcclusionScope& operator=(const OcclusionScope&) = delete;

private:
    TraceContext& mCtx;
    bool mWas;
};

}  // namespace kerf
