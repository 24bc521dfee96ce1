/// @file csg/tree/span.h
/// @brief Spans: the parameter ranges along a ray where the ray is inside a solid, and their
/// Boolean algebra (Roth 1982).
#pragma once

#include "csg/types.h"

#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace kerf {

/// One place where a ray crosses the boundary of a solid.
struct Boundary {
    double t = 0.0;
    /// Outward normal of the solid the span belongs to, in the space of whoever holds the span
    /// (not necessarily unit length). For the solid A − B, boundaries from B carry −n_B.
    Vec3 normal{0.0};
    /// Index into the scene's materials; kNoMaterial until a `material` modifier sets it
    /// (the innermost modifier wins, so outer ones only fill kNoMaterial).
    int32_t material = -1;
    /// Which primitive made this boundary (1-based, unique in the scene); 0 for a clip of the
    /// ray's parameter range, which is not a surface.
    uint32_t primitive = 0;
    /// A bound on |t − t*| / |t*| beyond rounding: 0 for closed forms, the tolerance the root
    /// was isolated to for root-found surfaces. Secondary rays start past this error.
    float relError = 0.f;

    static constexpr int32_t kNoMaterial = -1;
    /// No material yet, met from the back of a surface (csg/primitives/surfaces.h): an `interior`
    /// modifier fills these, a `material` modifier fills them as it fills kNoMaterial.
    static constexpr int32_t kNoMaterialBack = -2;
    bool hasMaterial() const { return material >= 0; }
    bool isSurface() const { return primitive != 0; }
};

/// The ray is inside the solid for in.t < t < out.t; in.t ≤ out.t. Unbounded solids use ±inf.
struct Span {
    Boundary in;
    Boundary out;
};

/// A sorted list of disjoint spans. Small-buffer storage: most lists hold a few spans, and the
/// hot path must not touch the heap. The inline buffer is raw storage, so an empty list costs
/// nothing to make (Boundary's default values would otherwise be written four times over).
class SpanList {
public:
    SpanList() = default;
    SpanList(const SpanList& o) { assign(o); }
    SpanList& operator=(const SpanList& o) {
        if (this != &o) {
            mSize = 0;
            assign(o);
        }
        return *this;
    }
    SpanList(SpanList&& o) noexcept { moveFrom(o); }
    SpanList& operator=(SpanList&& o) noexcept {
        if (this != &o) {
            release();
            moveFrom(o);
        }
        return *this;
    }
    ~SpanList() { release(); }

    int size() const { return mSize; }
    bool empty() const { return mSize == 0; }
    void clear() { mSize = 0; }
    Span& operator[](int i) { return mData[i]; }
    const Span& operator[](int i) const { return mData[i]; }
    Span* begin() { return mData; }
    Span* end() { return mData + mSize; }
    const Span* begin() const { return mData; }
    const Span* end() const { return mData + mSize; }
    Span& back() { return mData[mSize - 1]; }
    const Span& back() const { return mData[mSize - 1]; }
    void push_back(const Span& s) {
        if (mSize == mCapacity) grow();
        new (&mData[mSize++]) Span(s);
    }
    /// Keeps the first n spans (n ≤ size()); the storage stays.
    void truncate(int n) { mSize = n; }
    /// Copies o's spans into this list's storage (which grows only if it must).
    void assign(const SpanList& o) {
        while (mCapacity < o.mSize) grow();
        std::memcpy(static_cast<void*>(mData), o.mData, sizeof(Span) * o.mSize);
        mSize = o.mSize;
    }
    void swap(SpanList& o) noexcept {
        SpanList tmp(std::move(o));
        o = std::move(*this);
        *this = std::move(tmp);
    }

private:
    static constexpr int kInline = 4;
    static_assert(std::is_trivially_copyable<Span>::value &&
                      std::is_trivially_destructible<Span>::value,
                  "spans are copied with memcpy and never destroyed one by one");
    void grow();
    Span* inlineData() { return reinterpret_cast<Span*>(mInline); }
    void moveFrom(SpanList& o) {
        if (o.mData == o.inlineData()) {
            mData = inlineData();
            mCapacity = kInline;
            std::memcpy(static_cast<void*>(mData), o.mData, sizeof(Span) * o.mSize);
        } else {
            mData = o.mData;
            mCapacity = o.mCapacity;
            o.mData = o.inlineData();
            o.mCapacity = kInline;
        }
        mSize = o.mSize;
        o.mSize = 0;
    }
    void release() {
        if (mData != inlineData()) ::operator delete(static_cast<void*>(mData));
        mData = inlineData();
        mCapacity = kInline;
        mSize = 0;
    }

    alignas(Span) unsigned char mInline[kInline * sizeof(Span)];
    Span* mData = inlineData();
    int mSize = 0;
    int mCapacity = kInline;
};

enum class BoolOp { Union, Intersection, Difference, Xor };

/// out = a op b. Both inputs sorted and disjoint; so is the result. At equal t the
/// combination is decided as if the boundaries coincided exactly, so coincident faces leave no
/// zero-width sliver; then dropThinSpans removes what is thinner than its boundaries' error.
/// The boundary kept at such a tie depends only on the two boundaries (a clip yields to a
/// surface where the surface decides; surfaces go by primitive id), not on which operand is a.
/// Xor boundaries inside the other operand are flipped. `out` must not alias a or b.
void combineSpans(BoolOp op, const SpanList& a, const SpanList& b, double relTolerance,
                  SpanList& out);

/// Removes spans, and closes gaps, no wider than their two boundaries' own error relative to
/// |t|: max(relError of the two, capped at relTolerance) and never below 32 ulps. Closed-form
/// boundaries (relError 0) therefore keep sheets down to rounding; root-found ones lose what
/// is thinner than the tolerance they were found to. Unbounded spans never vanish.
void dropThinSpans(SpanList& s, double relTolerance);

/// Sets material on every boundary that has none yet (the innermost modifier wins).
void fillMaterial(SpanList& s, int32_t material);

}  // namespace kerf
