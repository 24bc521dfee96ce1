/// @file io/text_file.cpp
/// @brief Text files through the one checked write path (io/atomic_file.h).
#include "io/text_file.h"

namespace kerf {

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    const std::string error = replaceFile(path, "", text.data(), text.size());
    if (!error.empty()) throw TextWriteError(cannotWrite(path, error));
}

}  // namespace kerf
