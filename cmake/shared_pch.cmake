# Precompiled headers, built once per flag set and shared (WG_PCH).
#
# Every target used to precompile the same headers for itself: 23 precompiled headers of
# about 6 s each in a clean Release build (and 30 in the sanitizer build, one per one-file
# fuzzer), most of a minute of CI's two cores spent building the same file again. Targets
# compiled with the same flags can share one (REUSE_FROM). Clang refuses a header built
# with other sanitizer or fuzzer flags, or with a macro defined differently, so there is
# one owner per flag set:
#   wg_core         the libraries, the programs and the benchmarks;
#   wg_test_core    the test binaries (it adds gtest);
#   wg_fuzz_loader  the fuzzers (-fsanitize=fuzzer).
# A macro that only some targets define (WG_SOURCE_DIR, WG_HAVE_RUNTIME) is not in any of
# these headers, and a definition the owner lacks is accepted by both GCC and Clang.
set(WG_PCH_HEADERS <nlohmann/json.hpp> <string> <vector> <map> <optional> <memory>)

# Every library and executable defined in `dir` and the directories below it.
function(wg_targets_below dir out)
  get_property(found DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    wg_targets_below(${sub} below)
    list(APPEND found ${below})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# Called once, after every target exists, so that a new target shares without an edit here.
function(wg_share_precompiled_headers)
  if(NOT WG_PCH)
    return()
  endif()
  target_precompile_headers(wg_core PRIVATE ${WG_PCH_HEADERS})
  if(TARGET wg_test_core)
    target_precompile_headers(wg_test_core PRIVATE ${WG_PCH_HEADERS} <gtest/gtest.h>)
  endif()
  if(TARGET wg_fuzz_loader)
    target_precompile_headers(wg_fuzz_loader PRIVATE ${WG_PCH_HEADERS})
  endif()
  wg_targets_below(${PROJECT_SOURCE_DIR} targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|EXECUTABLE)$"
       OR target MATCHES "^(wg_core|wg_test_core|wg_fuzz_loader)$")
      continue()
    endif()
    get_target_property(options ${target} COMPILE_OPTIONS)
    if(target MATCHES "^wg_test_")
      set(owner wg_test_core)
    elseif(options MATCHES "-fsanitize=fuzzer(;|$)")
      set(owner wg_fuzz_loader)
    else()
      set(owner wg_core)
    endif()
    target_precompile_headers(${target} REUSE_FROM ${owner})
  endforeach()
endfunction()
