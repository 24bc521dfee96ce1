// libFuzzer target: model text -> Scene -> an 8x6 image at 1 sample per pixel on one thread
// (render/render), no image written. Work is capped so a single input cannot run for seconds:
// the bounce depth is limited to 4 whatever the model asks; the image size, samples and
// threads are fixed. Any crash, sanitizer report or hang (-timeout) is a bug.
#include "fuzz_common.h"
#include "lang/compile.h"
#include "render/render.h"

#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text;
    if (!kerf::fuzz::modelText(data, size, text)) return -1;
    kerf::DiagnosticSink sink;
    auto scene = kerf::compileString(text, kerf::fuzz::kModelName, sink, kerf::fuzz::limits());
    if (!scene) return 0;
    scene->settings.maxDepth = std::min(scene->settings.maxDepth, 4);
    kerf::RenderOptions options;
    options.width = 8;
    options.height = 6;
    options.spp = 1;
    options.threads = 1;
    (void)kerf::render(*scene, options);
    return 0;
}
