/// @file io/png_errors_quiet.h
/// @brief libpng's own stderr lines kept off stderr (io/png_errors_quiet.cpp).
#pragma once

namespace kerf {

/// Does nothing; called where images are first read, so that every executable reading images
/// links the interposers of io/png_errors_quiet.cpp (a static library's member is linked only
/// when something refers to it).
void keepPngErrorsQuiet();

}  // namespace kerf
