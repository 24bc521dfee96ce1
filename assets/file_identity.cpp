// File identity by stat(): a file rewritten in place changes its size or mtime, one replaced
// by a rename changes its inode.
#include "assets/file_identity.h"

#include <filesystem>
#include <system_error>

#include <sys/stat.h>

namespace kerf {

std::string canonicalPath(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : canonical.string();
}

std::optional<AssetFile> fileIdentity(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return std::nullopt;
    AssetFile file;
    file.path = canonicalPath(path);
    file.device = uint64_t(st.st_dev);
    file.inode = uint64_t(st.st_ino);
    file.size = uint64_t(st.st_size);
    file.mtimeNs = int64_t(st.st_mtim.tv_sec) * 1000000000 + int64_t(st.st_mtim.tv_nsec);
    return file;
}

}  // namespace kerf
