# Sanitizer and fuzzer instrumentation for the whole build (docs/robustness.md).
#
#   -DWG_SANITIZE=ON        AddressSanitizer + UndefinedBehaviorSanitizer on every target
#                           (GCC or Clang). UB is fatal (-fno-sanitize-recover) so a test that
#                           hits it fails. vptr is off: Debian's glslang is built without RTTI,
#                           and UBSan's vptr check needs the typeinfo of every polymorphic class.
#   -DWG_BUILD_FUZZERS=ON   libFuzzer targets in tests/fuzz/ (Clang only). Implies
#                           WG_SANITIZE and adds coverage instrumentation
#                           (-fsanitize=fuzzer-no-link) to every library, so the fuzzers see
#                           the edges of the loader, resolve, passes and emitters.
option(WG_SANITIZE "Build everything with AddressSanitizer + UndefinedBehaviorSanitizer" OFF)
option(WG_BUILD_FUZZERS "Build the libFuzzer targets in tests/fuzz (requires Clang)" OFF)

if(WG_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "WG_BUILD_FUZZERS needs Clang (libFuzzer); configure with "
                        "-DCMAKE_CXX_COMPILER=clang++ (found ${CMAKE_CXX_COMPILER_ID})")
  endif()
  set(WG_SANITIZE ON CACHE BOOL "" FORCE)
endif()

if(WG_SANITIZE)
  set(WG_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize=vptr
                         -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${WG_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined -fno-sanitize=vptr)
  if(WG_BUILD_FUZZERS)
    add_compile_options(-fsanitize=fuzzer-no-link)
  endif()
  message(STATUS "watergraph: sanitizers on (ASan + UBSan)")
endif()
