// The glTF pre-scan: one pass over the JSON with an explicit stack of open containers (no
// recursion the input controls), keeping only node children, primitive accessors and
// accessor counts; then the node graph is walked breadth first.
#include "mesh/gltf_prescan.h"
#include "mesh/mesh_loader.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace kerf {
namespace {

[[noreturn]] void gltfScanFail(const std::string& path, const std::string& what) {
    throw MeshError(path + ": " + what);
}

struct GltfPrimitive {
    int64_t indices = -1, position = -1, mode = 4;
};

/// One open object or array: the key of the value being read (escapes decoded), or its index.
/// An object remembers its keys: JSON readers differ on a repeated key (Assimp's takes the
/// first), so a repeat is refused rather than scanning other facts than the importer reads.
struct GltfFrame {
    bool array = false;
    uint64_t index = 0;
    std::string key;
    std::unordered_set<std::string> keys;
};

/// The hexadecimal value of a \u escape's four digits, or -1.
int hexQuad(std::string_view s) {
    int v = 0;
    for (char c : s) {
        const int d = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
        if (d < 0) return -1;
        v = v * 16 + d;
    }
    return v;
}

/// A string token's text with JSON's escapes decoded (\u as UTF-8, surrogates kept as
/// their own 3-byte codes: only equality with plain ASCII keys matters here), or nullopt when
/// an escape is malformed.
std::optional<std::string> decodeJsonString(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\') {
            out += raw[i];
            continue;
        }
        if (++i >= raw.size()) return std::nullopt;
        static constexpr std::string_view kNames = "\"\\/bfnrt", kMeant = "\"\\/\b\f\n\r\t";
        if (const size_t k = kNames.find(raw[i]); k != std::string_view::npos) {
            out += kMeant[k];
            continue;
        }
        if (raw[i] != 'u' || i + 5 > raw.size()) return std::nullopt;
        const int u = hexQuad(raw.substr(i + 1, 4));
        if (u < 0) return std::nullopt;
        i += 4;
        if (u < 0x80) {
            out += char(u);
        } else if (u < 0x800) {
            out += char(0xC0 | (u >> 6)), out += char(0x80 | (u & 0x3F));
        } else {
            out += char(0xE0 | (u >> 12)), out += char(0x80 | ((u >> 6) & 0x3F));
            out += char(0x80 | (u & 0x3F));
        }
    }
    return out;
}

/// The facts kept from the JSON, all indices as written (checked afterwards).
struct GltfFacts {
    uint64_t nodes = 0;
    std::vector<std::pair<uint64_t, int64_t>> children;  ///< (parent, child)
    std::vector<GltfPrimitive> primitives;
    std::vector<int64_t> accessorCounts;  ///< -1: no count given
};

class GltfJsonScanner {
public:
    GltfJsonScanner(const std::string& path, std::string_view json) : mPath(path), mJson(json) {}

    GltfFacts scan() {
        skipSpace();
        do {
            if (!value()) closeContainers();
        } while (!mStack.empty());
        skipSpace();
        if (mPos != mJson.size()) error("text after the JSON value");
        return std::move(mFacts);
    }

private:
    [[noreturn]] void error(const std::string& what) const {
        gltfScanFail(mPath, "glTF JSON is malformed at byte " + std::to_string(mPos) + ": " + what);
    }

    void skipSpace() {
        while (mPos < mJson.size() && std::strchr(" \t\r\n", mJson[mPos]) && mJson[mPos] != 0)
            ++mPos;
    }

    bool at(char c) {
        skipSpace();
        return mPos < mJson.size() && mJson[mPos] == c;
    }

    void expect(char c) {
        if (!at(c)) error(std::string("expected '") + c + "'");
        ++mPos;
    }

    std::string_view stringToken() {
        expect('"');
        const size_t start = mPos;
        while (mPos < mJson.size() && mJson[mPos] != '"') mPos += mJson[mPos] == '\\' ? 2 : 1;
        if (mPos >= mJson.size()) error("unterminated string");
        return mJson.substr(start, mPos++ - start);
    }

    /// Reads one value. An object or array is opened and left on the stack: true when it has
    /// members to read (its first key read), false when it is empty or the value a scalar.
    bool value() {
        skipSpace();
        if (mPos >= mJson.size()) error("unexpected end");
        noteValueStart();
        const char c = mJson[mPos];
        if (c == '{' || c == '[') return open(c == '[');
        if (c == '"')
            stringToken();
        else if (c == 't' || c == 'f' || c == 'n')
            literal();
        else
            number();
        return false;
    }

    bool open(bool array) {
        if (mStack.size() >= kGltfMaxJsonNesting)
            gltfScanFail(mPath, "glTF JSON nests deeper than " +
                                    std::to_string(kGltfMaxJsonNesting) + " levels");
        ++mPos;
        mStack.push_back({array, 0, {}, {}});
        if (at(array ? ']' : '}')) return false;  // empty: closed by closeContainers
        if (!array) readKey();
        mStack.back().index = 1;  // 1-based while inside: 0 means "empty, close me"
        return true;
    }

    void readKey() {
        const size_t at = mPos;
        std::optional<std::string> key = decodeJsonString(stringToken());
        if (!key) error("bad escape in a key");
        GltfFrame& top = mStack.back();
        if (!top.keys.insert(*key).second) {
            mPos = at;
            error("the key \"" + *key + "\" appears twice in one object");
        }
        top.key = std::move(*key);
        expect(':');
    }

    /// After a value: moves to the next member, or closes finished containers.
    void closeContainers() {
        while (!mStack.empty()) {
            GltfFrame& top = mStack.back();
            if (at(',') && top.index != 0) {
                ++mPos;
                ++top.index;
                if (!top.array) readKey();
                return;
            }
            expect(top.array ? ']' : '}');
            mStack.pop_back();
        }
    }

    void literal() {
        for (const char* word : {"true", "false", "null"})
            if (mJson.compare(mPos, std::strlen(word), word) == 0) {
                mPos += std::strlen(word);
                return;
            }
        error("unknown literal");
    }

    void number() {
        double v = 0.0;
        const char* first = mJson.data() + mPos;
        const auto [end, ec] = std::from_chars(first, mJson.data() + mJson.size(), v);
        if (ec == std::errc::invalid_argument || end == first) error("expected a value");
        mPos += size_t(end - first);
        noteNumber(ec == std::errc() ? v : std::nan(""));
    }

    bool pathIs(size_t depth, const char* key0) const {
        return depth >= 1 && mStack.size() == depth && !mStack[0].array && mStack[0].key == key0 &&
               (depth < 2 || mStack[1].array);
    }
    uint64_t indexAt(size_t level) const { return mStack[level].index - 1; }

    /// Counts array items of the arrays whose size matters, as each item starts.
    void noteValueStart() {
        if (pathIs(2, "nodes")) mFacts.nodes = indexAt(1) + 1;
        if (pathIs(2, "accessors")) mFacts.accessorCounts.push_back(-1);
        if (pathIs(4, "meshes") && mStack[2].key == "primitives" && mStack[3].array)
            mFacts.primitives.emplace_back();
    }

    void noteNumber(double v) {
        const int64_t n = (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9e15)
                              ? int64_t(v)
                              : std::numeric_limits<int64_t>::min();
        if (pathIs(4, "nodes") && mStack[2].key == "children" && mStack[3].array)
            mFacts.children.emplace_back(indexAt(1), n);
        if (pathIs(3, "accessors") && mStack[2].key == "count") mFacts.accessorCounts.back() = n;
        if (mFacts.primitives.empty() || !pathIs(mStack.size(), "meshes") || mStack.size() < 5 ||
            mStack[2].key != "primitives" || !mStack[3].array)
            return;
        GltfPrimitive& p = mFacts.primitives.back();
        if (mStack.size() == 5 && mStack[4].key == "indices") p.indices = n;
        if (mStack.size() == 5 && mStack[4].key == "mode") p.mode = n;
        if (mStack.size() == 6 && mStack[4].key == "attributes" && mStack[5].key == "POSITION")
            p.position = n;
    }

    const std::string& mPath;
    std::string_view mJson;
    size_t mPos = 0;
    std::vector<GltfFrame> mStack;
    GltfFacts mFacts;
};

/// Parents, cycles and depth of the node graph, without recursion. Children are kept flat
/// (offsets per node) so memory is a few bytes per node whatever the file.
void checkGltfNodeGraph(const std::string& path, const GltfFacts& facts) {
    const uint64_t n = facts.nodes;
    if (n >= std::numeric_limits<uint32_t>::max()) gltfScanFail(path, "too many glTF nodes");
    std::vector<uint32_t> parent(n, std::numeric_limits<uint32_t>::max()), first(n + 1, 0);
    for (const auto& [p, c] : facts.children) {
        if (p >= n) gltfScanFail(path, "glTF node " + std::to_string(p) + " is past the nodes");
        if (c < 0 || uint64_t(c) >= n)
            gltfScanFail(path, "glTF node " + std::to_string(p) + " has child " +
                                   (c < 0 ? "index out of range" : std::to_string(c)) +
                                   ", but the file has " + std::to_string(n) + " nodes");
        if (parent[c] != std::numeric_limits<uint32_t>::max())
            gltfScanFail(path, "glTF node " + std::to_string(c) +
                                   " is the child of two nodes (glTF allows one parent)");
        parent[c] = uint32_t(p);
        ++first[p + 1];
    }
    for (uint64_t i = 0; i < n; ++i) first[i + 1] += first[i];
    std::vector<uint32_t> kids(facts.children.size()), fill(first.begin(), first.end() - 1);
    for (const auto& [p, c] : facts.children) kids[fill[p]++] = uint32_t(c);
    std::vector<uint32_t> level, next;
    for (uint64_t i = 0; i < n; ++i)
        if (parent[i] == std::numeric_limits<uint32_t>::max()) level.push_back(uint32_t(i));
    uint64_t reached = 0;
    for (int depth = 0; !level.empty(); ++depth) {
        if (depth >= kMeshMaxNodeDepth)
            gltfScanFail(path, "node hierarchy deeper than " + std::to_string(kMeshMaxNodeDepth) +
                                   " levels");
        reached += level.size();
        next.clear();
        for (uint32_t v : level)
            next.insert(next.end(), kids.data() + first[v], kids.data() + first[v + 1]);
        std::swap(level, next);
    }
    if (reached < n) gltfScanFail(path, "glTF node hierarchy has a cycle");
}

/// The triangles the mode-4 primitives declare; each accessor they name must exist.
std::optional<uint64_t> declaredGltfTriangles(const std::string& path, const GltfFacts& facts) {
    const auto count = [&](int64_t accessor, const char* what) -> int64_t {
        if (accessor < 0) return -1;
        if (uint64_t(accessor) >= facts.accessorCounts.size())
            gltfScanFail(path, std::string("a glTF primitive's ") + what + " accessor " +
                                   std::to_string(accessor) + " does not exist (the file has " +
                                   std::to_string(facts.accessorCounts.size()) + ")");
        return facts.accessorCounts[accessor];
    };
    std::optional<uint64_t> total = 0;
    for (const GltfPrimitive& p : facts.primitives) {
        const int64_t indices = count(p.indices, "indices");
        const int64_t positions = count(p.position, "POSITION");
        const int64_t corners = p.indices >= 0 ? indices : positions;
        // Assimp counts a strip's or fan's triangles as corners - 2 (a line strip's segments
        // as corners - 1) in unsigned arithmetic: fewer corners ask for 2^32 faces.
        const int64_t least = p.mode == 5 || p.mode == 6 ? 3 : p.mode == 2 || p.mode == 3 ? 2 : 0;
        if (least > 0 && corners < least)
            gltfScanFail(path,
                         "a glTF primitive of mode " + std::to_string(p.mode) + " has " +
                             (corners < 0 ? "no corners" : std::to_string(corners) + " corners") +
                             ", fewer than the " + std::to_string(least) + " it needs");
        if (p.mode != 4 || corners < 0) total.reset();
        if (total) *total += uint64_t(corners) / 3;
    }
    return total;
}

}  // namespace

GltfDeclared prescanGltf(const std::string& path, std::string_view json) {
    const GltfFacts facts = GltfJsonScanner(path, json).scan();
    checkGltfNodeGraph(path, facts);
    return {declaredGltfTriangles(path, facts)};
}

std::string_view glbJsonChunk(std::string_view glb) {
    if (glb.size() < 20 || glb.compare(16, 4, "JSON") != 0) return {};
    uint32_t length;
    std::memcpy(&length, glb.data() + 12, 4);  // little-endian by the format
    if (length > glb.size() - 20) return {};
    return glb.substr(20, length);
}

}  // namespace kerf
