// Mesh files through Assimp. Assimp parses; this file checks what it returns (a null or
// incomplete scene, missing arrays, indices, finite coordinates) before anything is copied,
// flattens the node hierarchy into one mesh, and joins equal vertices across meshes.
#include "mesh/mesh_loader.h"
#include "mesh/gltf_prescan.h"
#include "mesh/mesh_loader_truncation.h"
#include "mesh/ply_line_end.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>
#include <unordered_map>

namespace kerf {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw MeshError(path + ": " + what);
}

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

/// The node transform in double: Assimp's matrices are row-major (a1..a4 is the first row).
struct NodeTransform {
    glm::dmat4 worldFromMesh{1.0};
    glm::dmat3 normalWorldFromMesh{1.0};
    bool mirrors = false;  ///< negative determinant: corners swap to keep outward faces outward
};

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    glm::dmat4 r;
    const double rows[4][4] = {{m.a1, m.a2, m.a3, m.a4},
                               {m.b1, m.b2, m.b3, m.b4},
                               {m.c1, m.c2, m.c3, m.c4},
                               {m.d1, m.d2, m.d3, m.d4}};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) r[col][row] = rows[row][col];
    return r;
}

struct Placement {
    const aiMesh* mesh;
    NodeTransform transform;
};

void collect(const aiScene& scene, const aiNode& node, const glm::dmat4& parent,
             std::vector<Placement>& out, const std::string& path, int depth) {
    // A hierarchy deeper than this is a cycle or a hostile file, not a model.
    if (depth > kMeshMaxNodeDepth)
        fail(path, "node hierarchy deeper than " + std::to_string(kMeshMaxNodeDepth) + " levels");
    const glm::dmat4 world = parent * toGlm(node.mTransformation);
    NodeTransform t;
    t.worldFromMesh = world;
    t.normalWorldFromMesh = glm::transpose(glm::inverse(glm::dmat3(world)));
    t.mirrors = glm::determinant(glm::dmat3(world)) < 0.0;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes == nullptr || node.mMeshes[i] >= scene.mNumMeshes ||
            scene.mMeshes == nullptr || scene.mMeshes[node.mMeshes[i]] == nullptr)
            fail(path, "a node refers to a mesh that does not exist");
        out.push_back({scene.mMeshes[node.mMeshes[i]], t});
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) {
        if (node.mChildren == nullptr || node.mChildren[i] == nullptr)
            fail(path, "a node has a missing child");
        collect(scene, *node.mChildren[i], world, out, path, depth + 1);
    }
}

/// Position, normal and UV of one vertex, compared exactly (with -0 equal to +0).
struct VertexKey {
    double v[8];
    bool operator==(const VertexKey& o) const {
        for (int i = 0; i < 8; ++i)
            if (v[i] != o.v[i]) return false;
        return true;
    }
};

struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = 1469598103934665603ull;
        for (double d : k.v) {
            const double z = d == 0.0 ? 0.0 : d;  // -0 and +0 are one vertex
            uint64_t bits;
            std::memcpy(&bits, &z, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
            h ^= h >> 29;
        }
        return static_cast<size_t>(h);
    }
};

void checkMeshFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) fail(path, "not a regular file");
    if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot be opened for reading");
    if (std::filesystem::file_size(path, ec) == 0) fail(path, "empty file");
    if (const auto why = binaryMeshTruncation(path)) fail(path, *why);
}

/// Assimp's file access for one mesh: the mesh itself and files in its folder or below
/// (OBJ's mtllib, glTF's buffers and images). A path that leaves the folder, by ".." or an
/// absolute path, is refused and remembered, so a downloaded mesh cannot make kerf read
/// another file of the user's. Paths are compared lexically: a symlink the user placed in
/// the folder is followed. A binary PLY Assimp would misread is given as bytes respelt in
/// memory (mesh/ply_line_end.h).
class FolderConfinedIO : public Assimp::DefaultIOSystem {
public:
    explicit FolderConfinedIO(const std::string& meshPath)
        : mMesh(std::filesystem::absolute(meshPath).lexically_normal()),
          mFolder(mMesh.parent_path()),
          mRespelt(plyWithCrLfHeaderEnd(meshPath)) {}

    bool Exists(const char* file) const override {
        return inFolder(file) && Assimp::DefaultIOSystem::Exists(file);
    }

    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (mRespelt && std::filesystem::absolute(file).lexically_normal() == mMesh) {
            auto* bytes = new uint8_t[mRespelt->size()];  // the stream owns it
            std::memcpy(bytes, mRespelt->data(), mRespelt->size());
            return new Assimp::MemoryIOStream(bytes, mRespelt->size(), true);
        }
        if (inFolder(file)) return Assimp::DefaultIOSystem::Open(file, mode);
        if (!mRefused) mRefused = file;
        return nullptr;
    }

    /// The first path refused, if any.
    const std::optional<std::string>& refused() const { return mRefused; }

private:
    bool inFolder(const char* file) const {
        const auto wanted = std::filesystem::absolute(file).lexically_normal();
        const auto [folderEnd, wantedEnd] =
            std::mismatch(mFolder.begin(), mFolder.end(), wanted.begin(), wanted.end());
        if (folderEnd == mFolder.end()) return true;
        if (!mRefused) mRefused = file;
        return false;
    }

    std::filesystem::path mMesh, mFolder;
    std::optional<std::string> mRespelt;
    mutable std::optional<std::string> mRefused;
};

/// Assimp's exceptions and failures as a MeshError naming the file (never the library's own
/// wording alone: std::bad_alloc and length errors say the mesh is too large).
const aiScene* readSceneOrFail(Assimp::Importer& importer, const std::string& path,
                               unsigned flags) {
    try {
        return importer.ReadFile(path, flags);
    } catch (const std::bad_alloc&) {
        fail(path, "the mesh is too large to load (the importer ran out of memory)");
    } catch (const std::length_error&) {
        fail(path, "the mesh is too large to load (a size in the file exceeds what fits)");
    } catch (const std::exception& e) {
        fail(path, std::string("not a readable mesh (") + e.what() + ")");
    }
}

/// Whether any face has more than three corners, with each mesh's primitive types set from
/// its faces: Assimp 5.2's Triangulate asserts (abort()) when the types claim polygons the
/// faces do not have, as a garbage ASCII PLY face row made them (kerf_fuzz_mesh).
bool needsTriangulation(aiScene& scene) {
    bool polygons = false;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        aiMesh* mesh = scene.mMeshes[m];
        if (mesh == nullptr || mesh->mFaces == nullptr) continue;
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const unsigned n = mesh->mFaces[f].mNumIndices;
            // n == 0: a garbage row, no corners, dropped with points and lines.
            const aiPrimitiveType type = n == 1   ? aiPrimitiveType_POINT
                                         : n == 2 ? aiPrimitiveType_LINE
                                         : n == 3 ? aiPrimitiveType_TRIANGLE
                                                  : aiPrimitiveType_POLYGON;
            if (n > 0) types |= static_cast<unsigned>(type);
        }
        mesh->mPrimitiveTypes = types;
        polygons = polygons || (types & aiPrimitiveType_POLYGON) != 0;
    }
    return polygons;
}

const aiScene* triangulateOrFail(Assimp::Importer& importer, const std::string& path) {
    try {
        return importer.ApplyPostProcessing(aiProcess_Triangulate);
    } catch (const std::bad_alloc&) {
        fail(path, "the mesh is too large to load (out of memory while triangulating)");
    }
}

/// The scene Assimp reads, triangulated and checked for the parts read later. Vertices are
/// not joined here (no aiProcess_JoinIdenticalVertices): Assimp's join merged a NaN vertex
/// into its neighbours before the finite check; MeshJoiner joins after checking.
const aiScene& importScene(Assimp::Importer& importer, const std::string& path) {
    auto* io = new FolderConfinedIO(path);
    importer.SetIOHandler(io);  // the importer owns it
    // ValidateDataStructure runs before triangulating and is load-bearing: without it,
    // Assimp 5.2's Triangulate read out of bounds (valgrind) on garbage indices of a short PLY.
    const aiScene* scene = readSceneOrFail(importer, path, aiProcess_ValidateDataStructure);
    if (scene != nullptr && needsTriangulation(const_cast<aiScene&>(*scene)))
        scene = triangulateOrFail(importer, path);
    if (io->refused())
        fail(path, "refers to " + *io->refused() +
                       ", outside the mesh's folder (a mesh may read only files beside it)");
    if (scene == nullptr) {
        const std::string why = importer.GetErrorString();
        fail(path, "not a readable mesh" + (why.empty() ? std::string() : " (" + why + ")"));
    }
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) fail(path, "incomplete scene (no mesh data)");
    if (scene->mRootNode == nullptr) fail(path, "the scene has no root node");
    return *scene;
}

/// Every vertex of every mesh of the scene finite, used or not, before anything is joined.
/// Assimp reads floats: a coordinate beyond ±3.4e38 (1e308 in an OBJ) arrives as infinity.
void checkFiniteVertices(const aiScene& scene, const std::string& path) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh* mesh = scene.mMeshes[m];
        if (mesh == nullptr || mesh->mVertices == nullptr) continue;
        for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
            const aiVector3D& v = mesh->mVertices[i];
            if (std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z))
                fail(path, "vertex " + std::to_string(i) + " has a non-finite coordinate (NaN)");
            if (std::isinf(v.x) || std::isinf(v.y) || std::isinf(v.z))
                fail(path, "vertex " + std::to_string(i) +
                               " has a non-finite coordinate: infinite, or beyond the "
                               "single-precision range (±3.4e38) the mesh reader holds");
        }
    }
}

/// A glTF's JSON scanned before Assimp's recursive importer sees it (see gltf_prescan.h).
std::optional<uint64_t> prescanGltfFile(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".gltf" && ext != ".glb") return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string_view json = ext == ".glb" ? glbJsonChunk(data) : std::string_view(data);
    return prescanGltf(path, json).triangles;
}

/// glTF: Assimp drops a triangle whose index is out of range, silently; the count tells.
void checkDeclaredTriangles(const aiScene& scene, const std::string& path,
                            std::optional<uint64_t> declared) {
    if (!declared) return;
    uint64_t read = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        if (scene.mMeshes[m] != nullptr) read += scene.mMeshes[m]->mNumFaces;
    if (read < *declared)
        fail(path, "vertex index out of range: the file declares " + std::to_string(*declared) +
                       " triangles, " + std::to_string(*declared - read) +
                       " of them with an index past the vertices");
}

/// Copies the placed meshes' triangles into one mesh, joining vertices equal in position,
/// normal and UV (each kept only when every mesh has it).
class MeshJoiner {
public:
    MeshJoiner(const std::string& path, bool keepNormals, bool keepUvs)
        : mPath(path), mKeepNormals(keepNormals), mKeepUvs(keepUvs) {
        mOut.source = path;
    }

    void add(const Placement& p) {
        const aiMesh& m = *p.mesh;
        mLocal.assign(m.mNumVertices, std::numeric_limits<uint32_t>::max());
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            if (m.mFaces == nullptr) fail(mPath, "a mesh has faces without indices");
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines
            if (face.mIndices == nullptr) fail(mPath, "a face has no indices");
            std::array<uint32_t, 3> tri{};
            for (int c = 0; c < 3; ++c) {
                const unsigned i = face.mIndices[c];
                if (i >= m.mNumVertices)
                    fail(mPath, "vertex index " + std::to_string(i) +
                                    " out of range (the mesh has " +
                                    std::to_string(m.mNumVertices) + " vertices)");
                if (mLocal[i] == std::numeric_limits<uint32_t>::max())
                    mLocal[i] = joinedVertex(m, p.transform, i);
                tri[c] = mLocal[i];
            }
            if (p.transform.mirrors) std::swap(tri[1], tri[2]);
            mOut.triangles.push_back(tri);
        }
    }

    TriangleMesh take() { return std::move(mOut); }

private:
    /// The joined index of vertex i of m, placed by its node.
    uint32_t joinedVertex(const aiMesh& m, const NodeTransform& transform, unsigned i) {
        const aiVector3D& a = m.mVertices[i];
        const Vec3 raw(a.x, a.y, a.z);
        const Vec3 pos = Vec3(transform.worldFromMesh * glm::dvec4(raw, 1.0));
        if (!allFinite(pos))
            fail(mPath, "vertex " + std::to_string(i) + " is not finite once placed by its node");
        VertexKey key{{pos.x, pos.y, pos.z, 0, 0, 0, 0, 0}};
        Vec3 normal(0.0);
        std::array<double, 2> uv{0.0, 0.0};
        if (mKeepNormals) {
            const aiVector3D& n = m.mNormals[i];
            normal = transform.normalWorldFromMesh * Vec3(n.x, n.y, n.z);
            const double len = glm::length(normal);
            // A zero or broken normal is kept as zero: shading falls back to the face.
            normal = (std::isfinite(len) && len > 0.0) ? normal / len : Vec3(0.0);
            key.v[3] = normal.x, key.v[4] = normal.y, key.v[5] = normal.z;
        }
        if (mKeepUvs) {
            const aiVector3D& t = m.mTextureCoords[0][i];
            uv = {std::isfinite(t.x) ? t.x : 0.0, std::isfinite(t.y) ? t.y : 0.0};
            key.v[6] = uv[0], key.v[7] = uv[1];
        }
        auto [it, inserted] =
            mJoined.try_emplace(key, static_cast<uint32_t>(mOut.positions.size()));
        if (inserted) {
            if (mOut.positions.size() == std::numeric_limits<uint32_t>::max())
                fail(mPath, "more than 2^32 - 1 vertices");
            mOut.positions.push_back(pos);
            if (mKeepNormals) mOut.normals.push_back(normal);
            if (mKeepUvs) mOut.uvs.push_back(uv);
        }
        return it->second;
    }

    const std::string& mPath;
    const bool mKeepNormals, mKeepUvs;
    TriangleMesh mOut;
    std::unordered_map<VertexKey, uint32_t, VertexKeyHash> mJoined;
    std::vector<uint32_t> mLocal;  // the current mesh's vertex -> joined index
};

TriangleMesh loadMeshUnguarded(const std::string& path) {
    checkMeshFile(path);
    const std::optional<uint64_t> declaredTriangles = prescanGltfFile(path);
    Assimp::Importer importer;
    const aiScene& scene = importScene(importer, path);
    checkFiniteVertices(scene, path);
    checkDeclaredTriangles(scene, path, declaredTriangles);

    std::vector<Placement> placements;
    collect(scene, *scene.mRootNode, glm::dmat4(1.0), placements, path, 0);

    // STL normals are per facet, not smooth-shading normals: dropping them joins by position.
    const bool isStl = lowerExtension(path) == ".stl";
    bool keepNormals = !isStl, keepUvs = true;
    for (const Placement& p : placements) {
        if (p.mesh->mNumVertices > 0 && p.mesh->mVertices == nullptr)
            fail(path, "a mesh has vertices without positions");
        keepNormals = keepNormals && p.mesh->mNormals != nullptr;
        keepUvs = keepUvs && p.mesh->mTextureCoords[0] != nullptr;
    }

    MeshJoiner joiner(path, keepNormals, keepUvs);
    for (const Placement& p : placements) joiner.add(p);
    TriangleMesh out = joiner.take();
    if (out.triangles.empty()) fail(path, "no triangles");
    return out;
}

}  // namespace

TriangleMesh loadMesh(const std::string& path) {
    try {
        return loadMeshUnguarded(path);
    } catch (const std::bad_alloc&) {
        fail(path, "the mesh is too large to load (out of memory)");
    } catch (const std::length_error&) {
        fail(path, "the mesh is too large to load (more elements than fit)");
    }
}

}  // namespace kerf
