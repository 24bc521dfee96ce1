// libFuzzer target: OpenSCAD CSG text -> parse tree -> Scene (lang/openscad_csg.h), the path of
// `kerf render model.csg`. Any crash, sanitizer report, hang or excessive memory is a bug;
// diagnostics are the expected answer to bad input.
#include "fuzz_common.h"
#include "lang/openscad_csg.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text;
    if (!kerf::fuzz::modelText(data, size, text)) return -1;  // -1: not added to the corpus
    kerf::DiagnosticSink sink;
    auto scene = kerf::compileOpenScadString(text, "/nonexistent-kerf-fuzz/input.csg", sink);
    (void)sink.format();
    (void)scene;
    return 0;
}
