// The one translation unit that holds Catch2's runner; every module's tests link it.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "io/image.h"

int main(int argc, char* argv[]) {
    // The test executables are not beside the image plug-in as kerf is: point them at it.
    kerf::setImagePluginPath(KERF_IMAGE_PLUGIN);
    return Catch::Session().run(argc, argv);
}
