/// @file lang/no_assets.h
/// @brief The asset provider of a compile that was given none: every asset is refused with a
/// clear reason, so a model that names no file compiles as before and one that does is an
/// error at the file's name. In Skip mode (a compile that already failed) every asset is
/// refused as skipped, so lowering reports nothing for it and opens no file.
#pragma once

#include "scene/assets.h"

namespace kerf {

class NoAssets final : public AssetProvider {
public:
    enum class Mode : uint8_t { Refuse, Skip };
    explicit NoAssets(Mode mode = Mode::Refuse) : mMode(mode) {}

    Loaded<MeshAsset> mesh(const std::string&) override { return refused<MeshAsset>(); }
    std::shared_ptr<const MeshAsset> meshOf(std::vector<Vec3>, std::vector<std::array<uint32_t, 3>>,
                                            std::string) override {
        return nullptr;
    }
    Loaded<LevelSetAsset> levelSet(const std::string&, const std::string&) override {
        return refused<LevelSetAsset>();
    }
    Loaded<FogAsset> fogVolume(const std::string&, const std::string&) override {
        return refused<FogAsset>();
    }
    Loaded<Texture> texture(const std::string&) override { return refused<Texture>(); }
    Loaded<TextShape> text(const TextRequest&) override { return refused<TextShape>(); }
    const std::vector<AssetFile>& inputs() const override { return mNone; }

    /// Why every asset is refused.
    static constexpr const char* kReason =
        "this compile was given no asset provider (assets/asset_cache.h), so it opens no file";

private:
    template <class T>
    Loaded<T> refused() const {
        Loaded<T> r;
        r.error.reason = kReason;
        r.error.skipped = mMode == Mode::Skip;
        return r;
    }
    Mode mMode;
    std::vector<AssetFile> mNone;
};

}  // namespace kerf
