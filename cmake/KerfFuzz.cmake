# KERF_FUZZ=ON builds the libFuzzer targets of tests/fuzz/ (kerf_fuzz_compile, kerf_fuzz_render).
# It needs clang (libFuzzer is clang's: Debian 12's clang 14 with libclang-rt-14-dev), so it is
# off by default and the normal build never needs clang. Every target of such a build is
# instrumented for coverage (-fsanitize=fuzzer-no-link) and checked by ASan + UBSan, any report
# fatal; scripts/test builds only the fuzz targets there (build-fuzz/), with tests off.
# See docs/robustness.md, "Fuzzing".
option(KERF_FUZZ "Build the libFuzzer targets (needs clang)" OFF)
if(KERF_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "KERF_FUZZ needs clang++ (libFuzzer): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++ (got ${CMAKE_CXX_COMPILER_ID})")
  endif()
  if(KERF_SANITIZE)
    message(FATAL_ERROR "KERF_FUZZ already builds with ASan + UBSan; leave KERF_SANITIZE off")
  endif()
  # Alignment recoverable, as in cmake/KerfSanitize.cmake, so tests/sanitizers/ubsan.supp can
  # name oneTBB's concurrent_hash_map (every OpenVDB tree's destructor reaches it: kerf_fuzz_vdb).
  set(KERF_FUZZ_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all
                           -fsanitize-recover=alignment -fno-omit-frame-pointer)
  add_compile_options(-fsanitize=fuzzer-no-link ${KERF_FUZZ_SANITIZERS})
  add_link_options(${KERF_FUZZ_SANITIZERS})
endif()
