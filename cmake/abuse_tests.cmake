# The abuse tests (docs/abuse_testing.md): C programs that link the FMU's own sources and play the
# master. Built in every build folder; instrumented when AK_SANITIZE is set (cmake/sanitizers.cmake).

# The FMU's sources, compiled once more as a static library the test programs link.
get_target_property(_ak_fmu_sources ${MODEL_IDENTIFIER} SOURCES)
add_library(ak_fmu_for_tests STATIC ${_ak_fmu_sources})
target_include_directories(ak_fmu_for_tests PUBLIC fmu_src "${FMI2_HEADERS_DIR}")
target_compile_options(ak_fmu_for_tests PRIVATE ${AK_WARNINGS})
target_link_libraries(ak_fmu_for_tests PUBLIC kinematics_core)

# The master's side shared by the programs: callbacks, the op table, state helpers.
add_library(ak_test_master STATIC
  fmu_src/test/fmi2_test_callbacks.c
  fmu_src/test/fmi2_test_ops.c
  fmu_src/test/fmi2_test_instance.c
  fmu_src/test/fmi2_bad_input_table.c)
target_compile_options(ak_test_master PRIVATE ${AK_WARNINGS})
target_link_libraries(ak_test_master PUBLIC ak_fmu_for_tests)

find_package(Threads REQUIRED)

if(NOT AK_FUZZ)
  add_executable(test_fmi2_calls fmu_src/test/test_fmi2_calls.c)
  target_compile_options(test_fmi2_calls PRIVATE ${AK_WARNINGS})
  target_link_libraries(test_fmi2_calls PRIVATE ak_test_master)
  add_test(NAME fmi2_calls COMMAND test_fmi2_calls)

  add_executable(test_fmi2_instances fmu_src/test/test_fmi2_instances.c)
  target_compile_options(test_fmi2_instances PRIVATE ${AK_WARNINGS})
  target_link_libraries(test_fmi2_instances PRIVATE ak_test_master Threads::Threads)
  add_test(NAME fmi2_instances COMMAND test_fmi2_instances 1000 4 20)

  add_executable(soak_fmi2 fmu_src/test/soak_fmi2.c)
  target_compile_options(soak_fmi2 PRIVATE ${AK_WARNINGS})
  target_link_libraries(soak_fmi2 PRIVATE ak_test_master)
  add_test(NAME fmi2_soak_short COMMAND soak_fmi2 100000)
else()
  add_executable(fuzz_fmi2 fmu_src/test/fuzz_fmi2.c)
  target_compile_options(fuzz_fmi2 PRIVATE ${AK_WARNINGS})
  target_link_libraries(fuzz_fmi2 PRIVATE ak_test_master)
  target_link_options(fuzz_fmi2 PRIVATE -fsanitize=fuzzer)
endif()
