/// @file io/plugin/jpeg_errors.cpp
/// @brief libjpeg's exit-on-error turned into a message (io/plugin/jpeg_errors.h).
#include "io/plugin/jpeg_errors.h"

#include <dlfcn.h>

#include <csetjmp>
#include <cstdio>

extern "C" {
#include <jpeglib.h>
}

namespace {

thread_local std::jmp_buf* tEscape = nullptr;  ///< set while runCatchingJpegErrors runs
thread_local char tMessage[JMSG_LENGTH_MAX];

using StdError = struct jpeg_error_mgr* (*)(struct jpeg_error_mgr*);
using Handler = void (*)(j_common_ptr);

/// libjpeg's jpeg_std_error and the handlers it installs, looked up once.
struct Defaults {
    StdError stdError;
    Handler errorExit;
    Handler outputMessage;
};

const Defaults& defaults() {
    static const Defaults d = [] {
        void* symbol = ::dlvsym(RTLD_NEXT, "jpeg_std_error", "LIBJPEG_6.2");
        if (symbol == nullptr) symbol = ::dlsym(RTLD_NEXT, "jpeg_std_error");
        const auto stdError = reinterpret_cast<StdError>(symbol);
        struct jpeg_error_mgr probe;
        stdError(&probe);
        return Defaults{stdError, probe.error_exit, probe.output_message};
    }();
    return d;
}

extern "C" void kerfJpegErrorExit(j_common_ptr cinfo) {
    if (tEscape == nullptr) return defaults().errorExit(cinfo);  // not ours: libjpeg's way
    cinfo->err->format_message(cinfo, tMessage);
    std::longjmp(*tEscape, 1);
}

extern "C" void kerfJpegOutputMessage(j_common_ptr cinfo) {
    if (tEscape == nullptr) defaults().outputMessage(cinfo);  // inside: kerf alone speaks
}

}  // namespace

/// Interposes libjpeg's: OpenImageIO resolves it in the plug-in's dlopen group, where the
/// plug-in comes first.
extern "C" __attribute__((visibility("default"))) struct jpeg_error_mgr* jpeg_std_error(
    struct jpeg_error_mgr* err) {
    struct jpeg_error_mgr* result = defaults().stdError(err);
    result->error_exit = kerfJpegErrorExit;
    result->output_message = kerfJpegOutputMessage;
    return result;
}

namespace kerf_plugin {

int runCatchingJpegErrors(int (*body)(void*), void* data, char* message, size_t messageSize) {
    std::jmp_buf escape;
    std::jmp_buf* const outer = tEscape;
    if (setjmp(escape) != 0) {
        tEscape = outer;
        if (messageSize > 0) std::snprintf(message, messageSize, "%s", tMessage);
        return -1;
    }
    tEscape = &escape;
    const int result = body(data);
    tEscape = outer;
    return result;
}

}  // namespace kerf_plugin
