// libFuzzer target: model text -> tokens -> AST -> Scene (lang/compileString), the path every
// `kerf check` and `kerf render` takes. Any crash, sanitizer report, hang (-timeout) or
// excessive memory (-rss_limit_mb) is a bug; diagnostics are the expected answer to bad input.
#include "fuzz_common.h"
#include "lang/compile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text;
    if (!kerf::fuzz::modelText(data, size, text)) return -1;  // -1: not added to the corpus
    kerf::DiagnosticSink sink;
    auto scene = kerf::compileString(text, kerf::fuzz::kModelName, sink, kerf::fuzz::limits());
    // Formatting the diagnostics is part of what the user sees: exercise it too.
    (void)sink.format();
    (void)scene;
    return 0;
}
