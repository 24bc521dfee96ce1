/// @file io/atomic_file.h
/// @brief Replacing a file all at once, the one path by which kerf writes every output
/// (images, text, CSV, SVG): the bytes go to a temporary file beside the target, every write,
/// the fsync, the close and the final size are checked, and only then is the temporary renamed
/// onto the target. On any failure the temporary is removed and the earlier file is untouched;
/// a signal mid-write removes the temporary too (io/temporary_files.h).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace kerf {

/// Thrown for an output that cannot be written; what() is "cannot write 'F': <reason>".
/// The image and text writers throw their own subclasses.
struct FileWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The message every writer gives: "cannot write 'F': <reason>".
std::string cannotWrite(const std::string& path, const std::string& reason);

/// Why `path` cannot be an output, or "" when it can: the file name is missing, its folder
/// does not exist or is not a folder, the path is a folder or not a regular file, or (when
/// `probe`) a file cannot be created in the folder (permissions, read-only file system, no
/// inodes left). Used before any work (the probe creates and removes one temporary file) and
/// to explain a failure to create the temporary.
std::string outputProblem(const std::string& path, bool probe);

/// Throws FileWriteError when outputProblem(path, true) finds a problem.
void checkOutputWritable(const std::string& path);

/// Replaces `path` with the `size` bytes at `data` through a temporary file
/// "dir/.name.kerf-tmp-XXXXXXXX<suffix>" created with the permissions a plain new file would
/// get (or those of the file it replaces). Returns "" on success, else the reason.
std::string replaceFile(const std::string& path, const std::string& suffix, const void* data,
                        size_t size);

}  // namespace kerf
