/// @file scene/limits.h
/// @brief Every limit kerf puts on its input, in one place (docs/robustness.md, "Limits").
/// lang/ checks them while reading and lowering a model, app/ checks the command line against
/// the same numbers, so a value accepted in a model is accepted as a flag and the other way
/// round. Depth limits exist because the code that walks that depth recurses: each is far
/// above what real models need and far below what overflows a thread's stack.
#pragma once

#include <cstdint>

namespace kerf {

// ---- files ----
/// Bytes read from one model or included file; larger files are refused before reading.
constexpr int64_t kMaxSourceBytes = int64_t(256) << 20;  // 256 MB
/// How deep includes may nest (a file including a file including …).
constexpr int kMaxIncludeDepth = 200;

// ---- depth ----
/// How deeply parentheses, vectors, unary minus, powers and solids may nest in one statement.
constexpr int kMaxNesting = 200;
/// The largest height of an expression tree (long chains like 1+1+…+1 count too).
constexpr int kMaxExpressionDepth = 1000;
/// How many named solids and lets may build on each other: a definition that uses only
/// literals is at level 1, one that uses a level-n name is at level n + 1. Counted on the
/// definitions, so it does not depend on the order they are written in.
constexpr int kMaxNameDepth = 1000;
/// The height of a compiled solid tree (Boolean, transform and material nodes over a
/// primitive, named solids counted as if written out): tracing recurses once per level.
constexpr int kMaxCsgDepth = 1000;
/// A backstop on the lowering recursion itself (solids, expressions and names together),
/// which the limits above keep it under except along a cycle of names.
constexpr int kMaxLoweringDepth = 2000;

// ---- evaluation (docs/language.md, "Limits") ----
/// How deeply function calls may nest (recursion included). Each call level costs a few
/// lowering levels, so this stays far below kMaxLoweringDepth.
constexpr int kMaxCallDepth = 100;
/// Iterations of all loops and list comprehensions, plus function calls (those not answered
/// from the memo), in one model together: about 10 to 30 seconds of evaluation.
constexpr int64_t kMaxLoopIterations = 100'000'000;
/// Elements of one list (a range turned into a list counts too): a value takes about 100
/// bytes, so the longest list takes about 100 MB.
constexpr int64_t kMaxListLength = 1'000'000;
/// Bytes of one string, written or built by concatenation.
constexpr int64_t kMaxStringLength = 1 << 20;
/// Primitives one model may build (each sphere, box, … counted once per time it is made;
/// a shared solid used again counts once). Checked as they are made, so a model that would
/// build more stops with an error long before memory runs out (a sphere in a wide union takes
/// about 560 bytes at the peak, measured on a loop of a million).
constexpr int64_t kMaxPrimitives = 4'000'000;
/// Nodes one model may make: primitives, Booleans, transforms, materials and motions, each
/// counted when it is made, so a loop placing one shared solid again and again counts every
/// placement (the primitive limit counts the shared solid once). A transformed instance in a
/// wide union takes about 1.1 kB at its peak (measured), so the limit keeps a tree under
/// about 4.5 GB and 40 s of lowering (a loop of 200 M placements reached 6 GB in 17 s and
/// went on). Primitives are nodes: kMaxPrimitives equals it, and names the common cause.
constexpr int64_t kMaxNodes = 4'000'000;

// ---- images ----
/// Image width and height in pixels, in a model's `render { }` and on the command line.
constexpr int kMaxImageSide = 32768;
/// Samples per pixel, in a model and on the command line.
constexpr int kMaxSamplesPerPixel = 65536;
/// Worker threads of one process (`--threads`): far above any machine's cores, far below the
/// 70,000 at which TBB's own thread creation crashes.
constexpr int kMaxThreads = 4096;

// ---- section views ----
/// Section planes, in a model and on the command line together: each one is a half-space every
/// object it crosses is intersected with, so every ray through such an object meets them all.
constexpr int kMaxSections = 64;

}  // namespace kerf
