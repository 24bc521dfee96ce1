// Finding a font file with fontconfig (the only file that includes its header). A pattern
// fontconfig cannot honour is not an error to fontconfig: it returns its best substitute,
// usually another family. We compare the family asked for with the families of the match
// and refuse a substitute, so a typo never renders in a different typeface unnoticed.

#include <fontconfig/fontconfig.h>
#include <sys/stat.h>

#include <cctype>
#include <memory>
#include <mutex>

#include "io/font_outline.h"

namespace kerf {
namespace {

// Family names compared as fontconfig compares them: case and spaces do not count.
std::string familyKey(const std::string& name) {
    std::string key;
    for (unsigned char c : name) {
        if (c != ' ') key.push_back(static_cast<char>(std::tolower(c)));
    }
    return key;
}

}  // namespace

bool isFontPath(const std::string& font) {
    if (font.find('/') != std::string::npos) return true;
    auto endsWith = [&](const char* ext) {
        std::string e(ext);
        if (font.size() < e.size()) return false;
        std::string tail = font.substr(font.size() - e.size());
        for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return tail == e;
    };
    return endsWith(".ttf") || endsWith(".otf") || endsWith(".ttc") || endsWith(".pfb");
}

namespace {

struct PatternDeleter {
    void operator()(FcPattern* p) const { FcPatternDestroy(p); }
};
using PatternPtr = std::unique_ptr<FcPattern, PatternDeleter>;

const char* const kListHint = "list the installed fonts with `fc-list : family style`";

FontLocation fontFileLocation(const std::string& font) {
    struct stat st {};
    if (::stat(font.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
        throw FontError(FontError::Subject::Font,
                        "font file '" + font + "' does not exist or is not a regular file");
    }
    return {font, 0, {}};
}

/// Whether one of the match's family names is `wanted`; `got` is its first.
bool matchHasFamily(FcPattern* match, const std::string& wanted, std::string& got) {
    // A match may carry several family names (e.g. "DejaVu Sans" and "DejaVu Sans
    // Condensed"); the wanted family must be one of them.
    bool same = false;
    FcChar8* name = nullptr;
    for (int i = 0; FcPatternGetString(match, FC_FAMILY, i, &name) == FcResultMatch; ++i) {
        std::string n = reinterpret_cast<const char*>(name);
        if (i == 0) got = n;
        if (familyKey(n) == familyKey(wanted)) same = true;
    }
    return same;
}

void checkMatchedStyle(FcPattern* match, const std::string& font, const std::string& wanted,
                       int wantedWeight, int wantedSlant) {
    // A style the family lacks is also substituted silently (a regular face for "bold"); the
    // outlines would be the regular ones, so it is refused too. Near weights are accepted
    // ("light" finds ExtraLight), a weight on the other side of regular is not.
    int gotWeight = FC_WEIGHT_REGULAR, gotSlant = FC_SLANT_ROMAN;
    FcPatternGetInteger(match, FC_WEIGHT, 0, &gotWeight);
    FcPatternGetInteger(match, FC_SLANT, 0, &gotSlant);
    FcChar8* gotStyle = nullptr;
    FcPatternGetString(match, FC_STYLE, 0, &gotStyle);
    const std::string style = gotStyle ? reinterpret_cast<const char*>(gotStyle) : "?";
    const bool heavyWanted = wantedWeight >= FC_WEIGHT_DEMIBOLD;
    const bool lightWanted = wantedWeight >= 0 && wantedWeight <= FC_WEIGHT_LIGHT;
    if ((heavyWanted && gotWeight < FC_WEIGHT_DEMIBOLD) ||
        (lightWanted && gotWeight > FC_WEIGHT_LIGHT) ||
        (wantedSlant > FC_SLANT_ROMAN && gotSlant == FC_SLANT_ROMAN)) {
        throw FontError(FontError::Subject::Font,
                        "font '" + font + "' has no such style (fontconfig would use '" +
                            (wanted.empty() ? std::string() : wanted + " ") + style + "')",
                        kListHint);
    }
}

}  // namespace

FontLocation findFont(const std::string& font, bool acceptSubstitute) {
    if (font.empty())
        throw FontError(FontError::Subject::Font, "the font name is empty", kListHint);
    if (isFontPath(font)) return fontFileLocation(font);

    // fontconfig's default configuration is shared process state: one lookup at a time.
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    if (!FcInit())
        throw FontError(FontError::Subject::Font,
                        "cannot initialise fontconfig to look up font '" + font + "'");

    PatternPtr pattern(FcNameParse(reinterpret_cast<const FcChar8*>(font.c_str())));
    if (!pattern)
        throw FontError(FontError::Subject::Font, "'" + font + "' is not a valid font pattern",
                        kListHint);
    std::string wanted;
    FcChar8* family = nullptr;
    if (FcPatternGetString(pattern.get(), FC_FAMILY, 0, &family) == FcResultMatch) {
        wanted = reinterpret_cast<const char*>(family);
    }

    // The style asked for, read before the defaults fill it in.
    int wantedWeight = -1, wantedSlant = -1;
    FcPatternGetInteger(pattern.get(), FC_WEIGHT, 0, &wantedWeight);
    FcPatternGetInteger(pattern.get(), FC_SLANT, 0, &wantedSlant);

    FcConfigSubstitute(nullptr, pattern.get(), FcMatchPattern);
    FcDefaultSubstitute(pattern.get());
    FcResult result = FcResultNoMatch;
    PatternPtr match(FcFontMatch(nullptr, pattern.get(), &result));
    FcChar8* file = nullptr;
    if (!match || FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) {
        throw FontError(FontError::Subject::Font, "no font found for '" + font + "'", kListHint);
    }

    if (!wanted.empty()) {
        std::string got;
        const bool same = matchHasFamily(match.get(), wanted, got);
        if (!same && acceptSubstitute) {
            int index = 0;
            FcPatternGetInteger(match.get(), FC_INDEX, 0, &index);
            return {reinterpret_cast<const char*>(file), index, got};
        }
        if (!same) {
            throw FontError(FontError::Subject::Font,
                            "font '" + wanted +
                                "' is not installed (fontconfig would substitute '" + got + "')",
                            kListHint);
        }
    }

    checkMatchedStyle(match.get(), font, wanted, wantedWeight, wantedSlant);
    int index = 0;
    FcPatternGetInteger(match.get(), FC_INDEX, 0, &index);
    return {reinterpret_cast<const char*>(file), index, {}};
}

std::string findFontFile(const std::string& font) { return findFont(font).file; }

}  // namespace kerf
