# Instrumented builds for the abuse tests (docs/abuse_testing.md), one build folder each:
#   -DAK_SANITIZE=address,undefined   AddressSanitizer + UndefinedBehaviorSanitizer
#   -DAK_SANITIZE=thread              ThreadSanitizer
#   -DAK_SANITIZE=fuzzer              libFuzzer + ASan + UBSan (clang only; build targets fuzz_fmi2_<Model>)
# Every target of the folder is instrumented, the FMU's code included. Any report is fatal
# (-fno-sanitize-recover), so a run that finishes is a run without findings.
set(AK_SANITIZE "" CACHE STRING "Sanitizers for every target: address,undefined | thread | fuzzer")

if(AK_SANITIZE)
  if(MSVC)
    message(FATAL_ERROR "AK_SANITIZE is for GCC and Clang")
  endif()
  set(_ak_sanitize_flags -g -fno-omit-frame-pointer -fno-sanitize-recover=all)
  if(AK_SANITIZE STREQUAL "fuzzer")
    if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
      message(FATAL_ERROR "AK_SANITIZE=fuzzer needs clang (CC=clang)")
    endif()
    # The fuzz target links -fsanitize=fuzzer itself (it brings main); everything else is only
    # instrumented for coverage.
    list(APPEND _ak_sanitize_flags -fsanitize=fuzzer-no-link,address,undefined)
    set(AK_FUZZ ON)
  else()
    list(APPEND _ak_sanitize_flags -fsanitize=${AK_SANITIZE})
  endif()
  add_compile_options(${_ak_sanitize_flags})
  if(AK_SANITIZE STREQUAL "fuzzer")
    add_link_options(-fsanitize=address,undefined)
  else()
    add_link_options(-fsanitize=${AK_SANITIZE})
  endif()
  message(STATUS "Sanitizers: ${AK_SANITIZE}")
endif()
