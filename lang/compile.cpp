// The front door: read, check, tokenize and parse each file, splice included files in place
// (each file once; cycles and missing files are errors at the include), then lower.
#include "lang/compile.h"

#include "lang/lexer.h"
#include "lang/lower.h"
#include "lang/no_assets.h"
#include "lang/parser.h"
#include "lang/source.h"

#include <filesystem>
#include <set>

namespace kerf {

namespace {

namespace fs = std::filesystem;

/// A path that identifies a file however it was spelt (for "read once" and cycles).
std::string identity(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) p = fs::path(path).lexically_normal();
    return p.string();
}

class Loader {
public:
    Loader(DiagnosticSink& sink, AssetProvider& assets) : mSink(sink), mAssets(assets) {}

    /// Parses one file's text and everything it includes into `out`.
    void addText(const SourceText& source, Program& out) {
        const std::string id = identity(*source.name);
        mRead.insert(id);
        mSink.rememberSource(source.name, source.text);
        if (!checkSourceText(source, mSink)) return;
        TokenStream tokens(source, mSink);
        Program program = parse(tokens, mSink);
        mStack.push_back({id, *source.name});
        for (auto& arena : program.arenas) out.arenas.push_back(std::move(arena));
        // Moved one by one from the front, so the two deques never both hold every statement.
        while (!program.statements.empty()) {
            Statement& s = program.statements.front();
            if (s.kind == Statement::Kind::Include)
                include(s, *source.name, out);
            else
                out.statements.push_back(std::move(s));
            program.statements.pop_front();
        }
        mStack.pop_back();
    }

private:
    void include(const Statement& s, const std::string& includer, Program& out) {
        if (s.name.empty()) {
            mSink.error(s.loc, "include needs a file name");
            return;
        }
        const std::string name =
            (fs::path(includer).parent_path() / s.name).lexically_normal().string();
        const std::string id = identity(name);
        for (size_t i = 0; i < mStack.size(); ++i) {
            if (mStack[i].first != id) continue;
            std::string chain;
            for (size_t k = i; k < mStack.size(); ++k) chain += mStack[k].second + " → ";
            mSink.error(s.loc, "include cycle: " + chain + name);
            return;
        }
        if (mRead.count(id)) return;  // each file is read once
        // The include recursion is as deep as the chain of files: bound it before going deeper.
        if (mStack.size() >= static_cast<size_t>(kMaxIncludeDepth)) {
            mSink.error(s.loc,
                        "includes nested too deeply (more than " +
                            std::to_string(kMaxIncludeDepth) + " files, from " +
                            mStack.front().second + ")",
                        "include the parts from one file instead of from each other");
            return;
        }
        std::string why;
        auto bytes = readFileBytes(name, why);
        if (!bytes) {
            mSink.error(s.loc, "cannot read included file '" + s.name + "': " + why,
                        "includes are relative to the including file's folder; looked for " + name);
            return;
        }
        mAssets.sourceRead(name);
        addText(SourceText{std::make_shared<const std::string>(name),
                           std::make_shared<const std::string>(std::move(*bytes))},
                out);
    }

    DiagnosticSink& mSink;
    AssetProvider& mAssets;  ///< told of each included file, so no output replaces it
    std::set<std::string> mRead;
    std::vector<std::pair<std::string, std::string>> mStack;  // identity, name as shown
};

std::optional<Scene> compileSource(const SourceText& source, DiagnosticSink& sink,
                                   AssetProvider& assets, EvalLimits limits, SequenceFrame frame) {
    const int errorsBefore = sink.errorCount();
    const size_t diagnosticsBefore = sink.diagnostics().size();
    Program program;
    Loader(sink, assets).addText(source, program);
    // Lowering runs even after syntax errors: broken definitions keep their names, so the
    // semantic errors found are real ones, not echoes of the syntax error. It opens no asset
    // then: the compile fails anyway, and a hostile mesh or volume would only cost time.
    NoAssets skipped(NoAssets::Mode::Skip);
    const bool syntaxFailed = sink.errorCount() > errorsBefore;
    Lowering lowering(sink, syntaxFailed ? skipped : assets, limits);
    lowering.setSequenceFrame(frame);
    std::optional<Scene> scene = lowering.lower(program);
    sink.sortByLocation(diagnosticsBefore);
    if (sink.errorCount() > errorsBefore) return std::nullopt;
    return scene;
}

}  // namespace

std::optional<Scene> compileFile(const std::string& path, DiagnosticSink& sink,
                                 AssetProvider& assets, EvalLimits limits, SequenceFrame frame) {
    const std::optional<SourceText> source = readModelFile(path, sink);
    if (!source) return std::nullopt;
    assets.sourceRead(path);
    return compileSource(*source, sink, assets, limits, frame);
}

std::optional<Scene> compileFile(const std::string& path, DiagnosticSink& sink, EvalLimits limits,
                                 SequenceFrame frame) {
    NoAssets none;
    return compileFile(path, sink, none, limits, frame);
}

std::optional<Scene> compileString(const std::string& text, const std::string& name,
                                   DiagnosticSink& sink, AssetProvider& assets, EvalLimits limits,
                                   SequenceFrame frame) {
    return compileSource(SourceText{std::make_shared<const std::string>(name),
                                    std::make_shared<const std::string>(text)},
                         sink, assets, limits, frame);
}

std::optional<Scene> compileString(const std::string& text, const std::string& name,
                                   DiagnosticSink& sink, EvalLimits limits, SequenceFrame frame) {
    NoAssets none;
    return compileString(text, name, sink, none, limits, frame);
}

}  // namespace kerf
