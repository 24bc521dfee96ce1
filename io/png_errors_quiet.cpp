/// @file io/png_errors_quiet.cpp
/// @brief libpng's own "libpng error: …" and "libpng warning: …" lines kept off stderr.
///
/// OpenImageIO's PNG reader gives libpng an error handler that records the message and
/// returns; libpng then calls its default handler, which prints the message to stderr before
/// it longjmps. kerf reports the error itself (OpenImageIO's recorded text, with the file), so
/// the printed line is noise ahead of kerf's message. These two definitions interpose libpng's:
/// they live in the executable, which comes first in the global scope (FreeType already loads
/// libpng there, so an interposer in the image plug-in would never be reached). Each error
/// handler given is wrapped: the wrapper calls it, then longjmps as libpng's default would, but
/// silently; a missing warning handler becomes a silent one.
#include "io/png_errors_quiet.h"

#include <dlfcn.h>

#include <mutex>
#include <unordered_map>

extern "C" {
struct png_struct_def;
using PngStruct = png_struct_def*;
using PngErrorFn = void (*)(PngStruct, const char*);
}

namespace {

using CreateRead = PngStruct (*)(const char*, void*, PngErrorFn, PngErrorFn);
using SetErrorFn = void (*)(PngStruct, void*, PngErrorFn, PngErrorFn);
using LongJmp = void (*)(PngStruct, int);

/// libpng's own functions, found after the executable in the search order.
struct RealPng {
    CreateRead createRead;
    SetErrorFn setErrorFn;
    LongJmp longJmp;
};

void* realPngSymbol(const char* name) {
    void* symbol = ::dlvsym(RTLD_NEXT, name, "PNG16_0");
    if (symbol == nullptr) symbol = ::dlsym(RTLD_NEXT, name);
    if (symbol != nullptr) return symbol;
    // libpng loaded only inside a dlopen group (its caller must have loaded it).
    void* png = ::dlopen("libpng16.so.16", RTLD_LAZY | RTLD_NOLOAD);
    return png != nullptr ? ::dlsym(png, name) : nullptr;
}

const RealPng& realPng() {
    static const RealPng real{reinterpret_cast<CreateRead>(realPngSymbol("png_create_read_struct")),
                              reinterpret_cast<SetErrorFn>(realPngSymbol("png_set_error_fn")),
                              reinterpret_cast<LongJmp>(realPngSymbol("png_longjmp"))};
    return real;
}

/// The error handler each read struct was given (nullptr: none), by struct. An entry is
/// replaced when a struct at the same address is made again; a few bytes per PNG read.
std::mutex gPngHandlersMutex;
std::unordered_map<PngStruct, PngErrorFn> gPngHandlers;
thread_local PngErrorFn tPngCreating = nullptr;  ///< the handler of a struct being made

PngErrorFn handlerOf(PngStruct png) {
    std::lock_guard<std::mutex> lock(gPngHandlersMutex);
    const auto it = gPngHandlers.find(png);
    return it != gPngHandlers.end() ? it->second : tPngCreating;
}

void remember(PngStruct png, PngErrorFn handler) {
    std::lock_guard<std::mutex> lock(gPngHandlersMutex);
    gPngHandlers[png] = handler;
}

void kerfQuietPngWarning(PngStruct, const char*) {}

void kerfQuietPngError(PngStruct png, const char* message) {
    if (const PngErrorFn handler = handlerOf(png)) handler(png, message);  // may not return
    realPng().longJmp(png, 1);  // what libpng's default does, without its line on stderr
}

}  // namespace

namespace kerf {
void keepPngErrorsQuiet() {}
}  // namespace kerf

extern "C" __attribute__((visibility("default"))) PngStruct png_create_read_struct(
    const char* version, void* errorPtr, PngErrorFn errorFn, PngErrorFn warnFn) {
    const RealPng& real = realPng();
    const PngErrorFn outer = tPngCreating;
    tPngCreating = errorFn;
    PngStruct png = real.createRead(version, errorPtr, kerfQuietPngError,
                                    warnFn != nullptr ? warnFn : kerfQuietPngWarning);
    tPngCreating = outer;
    if (png != nullptr) remember(png, errorFn);
    return png;
}

extern "C" __attribute__((visibility("default"))) void png_set_error_fn(PngStruct png,
                                                                        void* errorPtr,
                                                                        PngErrorFn errorFn,
                                                                        PngErrorFn warnFn) {
    // libpng itself may call this while making a struct, with the wrapper already in place.
    if (errorFn != kerfQuietPngError) remember(png, errorFn);
    realPng().setErrorFn(png, errorPtr, kerfQuietPngError,
                         warnFn != nullptr ? warnFn : kerfQuietPngWarning);
}
