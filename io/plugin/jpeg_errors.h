/// @file io/plugin/jpeg_errors.h
/// @brief libjpeg errors as messages instead of an exit. OpenImageIO 2.4's JPEG writer keeps
/// libjpeg's default error manager, whose error_exit prints libjpeg's own text and calls
/// exit(). The plug-in defines jpeg_std_error, which OpenImageIO (loaded in the plug-in's
/// dlopen group, after it) binds to: it calls libjpeg's and then points error_exit at a
/// handler that, inside runCatchingJpegErrors, keeps the message and jumps back out.
#pragma once

#include <cstddef>

namespace kerf_plugin {

/// Runs body(data) and returns its result; when libjpeg fails inside it, returns -1 with
/// libjpeg's message in `message` instead of letting libjpeg end the process. The objects
/// abandoned on that path (the encoder and its buffers) are leaked, never touched again: kerf
/// reports the error and exits.
int runCatchingJpegErrors(int (*body)(void*), void* data, char* message, size_t messageSize);

}  // namespace kerf_plugin
