// Lowering, part 3e: `volume "file.vdb" grid "name"`, a level set read from a .vdb file
// (by the asset provider, scene/assets.h) as a solid. The path is relative to the model file, as a
// mesh's is; each (file, grid) is read once per compile and its samples shared by every use. A file
// that cannot be a solid is an error at the file's string, or at the grid's name when the grid is
// what is wrong.
#include "lang/lower.h"

#include <filesystem>
#include <system_error>

namespace kerf {

namespace {

namespace fs = std::filesystem;

}  // namespace

NodePtr Lowering::lowerVolume(const Solid& s) {
    const PropertyBlock b(s.properties,
                          {{"file", PropertyType::Word, true}, {"grid", PropertyType::Word}},
                          "volume", s.loc, mSink);
    const Property* file = b.find("file");
    if (!b.ok() || !file || !file->expr) return nullptr;
    const SourcePos at = file->valueLoc();
    const auto v = evaluate(*file->expr, nullptr);
    if (!v) return nullptr;
    if (v->type != Value::Type::String || v->string().empty()) {
        error(at, "volume expects a .vdb file name in quotes", "write e.g. 'volume \"bunny.vdb\"'");
        return nullptr;
    }
    std::string gridName;
    SourcePos gridAt = at;
    if (const Property* grid = b.find("grid"); grid && grid->expr) {
        gridAt = grid->valueLoc();
        const auto g = evaluate(*grid->expr, nullptr);
        if (!g) return nullptr;
        if (g->type != Value::Type::String || g->string().empty()) {
            error(gridAt, "grid expects the grid's name in quotes, got " + typeName(g->type),
                  "write e.g. 'volume \"smoke.vdb\" grid \"surface\"'");
            return nullptr;
        }
        gridName = g->string();
    }
    const std::string& written = v->string();
    const std::string path = resolvedPath(written, at);
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    const auto key = std::make_pair(ec ? path : canonical.string(), gridName);
    auto it = mVolumeFiles.find(key);
    if (it == mVolumeFiles.end()) {
        Loaded<LevelSetAsset> grid = mAssets.levelSet(path, gridName);
        if (!grid && !grid.error.skipped)
            error(
                grid.error.subject == AssetError::Subject::Part && !gridName.empty() ? gridAt : at,
                "cannot use volume '" + written + "' as a solid: " + grid.error.reason,
                path == written
                    ? std::string()
                    : "volume files are relative to the model file's folder; looked for " + path);
        it = mVolumeFiles.emplace(key, grid.value).first;  // a failure is reported once
    }
    return it->second ? it->second->leaf() : nullptr;
}

}  // namespace kerf
