# KERF_SANITIZE=ON builds everything (libraries, the kerf executable, the image plug-in and the
# tests) with AddressSanitizer and UndefinedBehaviorSanitizer; any report aborts the process
# (-fno-sanitize-recover=all), so a report fails the test that produced it. scripts/test builds
# it as a second, Debug -O1 build in build-asan/ (docs/robustness.md, "Sanitizers").
#
# - The flags apply to every target, so the ASan runtime is linked into each executable and the
#   dlopen'ed image plug-in is instrumented the same way (it resolves the runtime from the
#   executable that loads it).
# - float-cast-overflow is not part of GCC's -fsanitize=undefined: it is added so an out-of-range
#   double -> int conversion (a pixel count, an index) is a report. float-divide-by-zero is not
#   enabled: kerf divides by zero on purpose (IEEE inf in interval arithmetic and ray slabs).
# - Reports from third-party code (TBB, OpenImageIO and its libraries) are suppressed only through
#   tests/sanitizers/*.supp, which name those libraries and never kerf's own code; ctest runs
#   every test with ASAN_OPTIONS/UBSAN_OPTIONS/LSAN_OPTIONS pointing at them (tests/CMakeLists.txt).
option(KERF_SANITIZE "Build with -fsanitize=address,undefined (any report is fatal)" OFF)
if(KERF_SANITIZE)
  set(KERF_SANITIZE_FLAGS
      -fsanitize=address,undefined,float-cast-overflow
      -fno-sanitize-recover=all
      # Alignment alone is recoverable, so tests/sanitizers/ubsan.supp can name oneTBB's header
      # (UBSan suppresses only recoverable checks); UBSAN_OPTIONS=halt_on_error=1 still ends
      # the process at any other alignment report.
      -fsanitize-recover=alignment
      -fno-omit-frame-pointer)
  add_compile_options(${KERF_SANITIZE_FLAGS})
  add_link_options(${KERF_SANITIZE_FLAGS})
endif()
