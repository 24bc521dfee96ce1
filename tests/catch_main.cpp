// The one translation unit that holds Catch2's runner; every module's tests link it.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
