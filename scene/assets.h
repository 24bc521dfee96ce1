/// @file scene/assets.h
/// @brief The files a model names (meshes, .vdb level sets and fog volumes, image textures,
/// fonts), as lowering asks for them. lang/ names an asset and gets it, or a reason it cannot
/// be had, through `AssetProvider`; it never opens a file itself. assets/asset_cache.h
/// implements the provider with a cache that outlives one compile.
#pragma once

#include "csg/profiles/profile_path.h"
#include "csg/tape/scalar_field.h"
#include "csg/tree/node.h"
#include "csg/types.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace kerf {

class Texture;  // io/texture.h: scene/ only holds it

/// Why an asset cannot be used. Lowering turns it into a diagnostic at the value at fault.
struct AssetError {
    /// What is wrong, without the file's name (lowering names the file as it was written).
    std::string reason;
    /// File: the file (or font) named is at fault. Part: the file was read and the part named
    /// inside it is (a .vdb's grid, a character of a text).
    enum class Subject : uint8_t { File, Part } subject = Subject::File;
    /// The reason is a whole message to show as it is (image support missing).
    bool standalone = false;
    /// Not opened because the compile has already failed (a syntax error): lowering reports
    /// nothing for it, and no hostile file is read for a model that cannot be used anyway.
    bool skipped = false;
    std::string hint;
};

/// An asset, or why it cannot be had.
template <class T>
struct Loaded {
    std::shared_ptr<const T> value;
    AssetError error;  ///< meaningful when value is null
    explicit operator bool() const { return value != nullptr; }
};

/// A triangle mesh, shared by every use of its file: each use makes its own leaf over the same
/// triangles, so a diagnostic about one use names that use.
class MeshAsset {
public:
    virtual ~MeshAsset() = default;
    /// A new leaf (NodeKind::Mesh) over the shared shape.
    virtual NodePtr leaf(bool smooth) const = 0;
    /// Closed, 2-manifold and consistently oriented: it can be a CSG operand.
    virtual bool isSolid() const = 0;
    /// Why it is not a solid: its first bad edge described (mesh/half_edges.h); empty for a
    /// solid, or when no edge is bad (no triangle at all).
    virtual std::string whyNotSolid() const = 0;
    /// Where the triangles came from, as messages name it.
    virtual const std::string& source() const = 0;
};

/// A level set read from a .vdb file; each use makes its own solid leaf over the samples.
class LevelSetAsset {
public:
    virtual ~LevelSetAsset() = default;
    virtual NodePtr leaf() const = 0;
};

/// A fog volume read from a .vdb file: its density and the box of its active voxels.
struct FogAsset {
    std::shared_ptr<const ScalarField> density;
    Bounds3 bounds;
};

/// One line of text to lay out in a font (io/font_outline.h's TextSpec, which assets/ maps
/// this onto).
struct TextRequest {
    enum class HAlign : uint8_t { Left, Center, Right, AdvanceCenter };
    enum class VAlign : uint8_t { Baseline, Top, Center, Bottom };
    std::string text;                  ///< one line of UTF-8
    std::string font = "DejaVu Sans";  ///< a fontconfig pattern, or a font file's path
    /// A relative font file path is taken relative to this folder (the model file's).
    std::string folder;
    double size = 1.0;
    HAlign halign = HAlign::Left;
    VAlign valign = VAlign::Baseline;
    double spacing = 1.0;
    /// Take the family fontconfig substitutes for one not installed (OpenSCAD's behaviour).
    bool acceptSubstitute = false;
};

/// The laid-out text: one shape per glyph with ink, and all of them in one even-odd shape
/// (the text exactly when no two glyphs share a point).
struct TextShape {
    std::vector<PathShape> glyphs;
    PathShape shape;
    bool glyphsOverlap = false;
    std::string substitutedFamily;  ///< the family used instead of the one asked for, if any
};

/// A file an asset was read from: its canonical path and what identifies its contents.
struct AssetFile {
    std::string path;  ///< canonical
    uint64_t device = 0, inode = 0, size = 0;
    int64_t mtimeNs = 0;
    bool operator==(const AssetFile& o) const {
        return path == o.path && device == o.device && inode == o.inode && size == o.size &&
               mtimeNs == o.mtimeNs;
    }
};

/// What lowering gets assets from. Paths are already resolved against the model file's
/// folder. Every call may open files; the provider lists each one it opened (inputs()).
class AssetProvider {
public:
    virtual ~AssetProvider() = default;
    virtual Loaded<MeshAsset> mesh(const std::string& path) = 0;
    /// A mesh from triangles made in the model (OpenSCAD's polyhedron): counter-clockwise
    /// seen from outside; `source` names it in messages. No file is opened.
    virtual std::shared_ptr<const MeshAsset> meshOf(std::vector<Vec3> positions,
                                                    std::vector<std::array<uint32_t, 3>> triangles,
                                                    std::string source) = 0;
    /// The level set `grid` of a .vdb (empty: its only one).
    virtual Loaded<LevelSetAsset> levelSet(const std::string& path, const std::string& grid) = 0;
    /// The fog volume `grid` of a .vdb (empty: its only one).
    virtual Loaded<FogAsset> fogVolume(const std::string& path, const std::string& grid) = 0;
    virtual Loaded<Texture> texture(const std::string& path) = 0;
    virtual Loaded<TextShape> text(const TextRequest& request) = 0;
    /// Every file opened for the assets asked for since this provider was made or last
    /// cleared, each once, in the order first used.
    virtual const std::vector<AssetFile>& inputs() const = 0;
    /// A model or included file the compile read: listed in inputs() like an asset's file, so
    /// no output replaces it. Providers that keep no list ignore it.
    virtual void sourceRead(const std::string& path) { (void)path; }
};

}  // namespace kerf
