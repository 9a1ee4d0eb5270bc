# Included by the top-level CMakeLists.txt. One libFuzzer target per input
# surface: fuzz/<name>_fuzz.cpp, with the library it exercises.
set(CLIPS_FUZZ_TARGETS sexpr pddl plan dataset utterance completions chat)
set(clips_fuzz_lib_sexpr clips_pddl)
set(clips_fuzz_lib_pddl clips_pddl)
set(clips_fuzz_lib_plan clips_pddl)
set(clips_fuzz_lib_dataset clips_data)
set(clips_fuzz_lib_utterance clips_lm)
set(clips_fuzz_lib_completions clips_lm)
set(clips_fuzz_lib_chat clips_lm)

if(CLIPS_FUZZ)
  set(fuzz_bins)
  foreach(t ${CLIPS_FUZZ_TARGETS})
    add_executable(${t}_fuzz ${CMAKE_SOURCE_DIR}/fuzz/${t}_fuzz.cpp)
    target_include_directories(${t}_fuzz PRIVATE ${CMAKE_SOURCE_DIR})
    target_compile_definitions(${t}_fuzz PRIVATE CLIPS_LIBFUZZER)
    target_link_libraries(${t}_fuzz PRIVATE ${clips_fuzz_lib_${t}})
    target_link_options(${t}_fuzz PRIVATE -fsanitize=fuzzer)
    set_target_properties(${t}_fuzz PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
    list(APPEND fuzz_bins ${t}_fuzz)
  endforeach()
  add_custom_target(fuzz_targets DEPENDS ${fuzz_bins})
else()
  # The normal (GCC) build: every seed and regression input replayed through
  # the same target functions, and a short libFuzzer run of each target when
  # `make fuzz-build` has built them (fuzz/smoke.sh skips otherwise).
  set(fuzz_srcs)
  foreach(t ${CLIPS_FUZZ_TARGETS})
    list(APPEND fuzz_srcs ${CMAKE_SOURCE_DIR}/fuzz/${t}_fuzz.cpp)
  endforeach()
  add_executable(test_fuzz ${CMAKE_SOURCE_DIR}/tests/fuzz/replay_test.cpp ${fuzz_srcs})
  target_include_directories(test_fuzz PRIVATE ${CMAKE_SOURCE_DIR} ${CMAKE_SOURCE_DIR}/tests)
  target_compile_definitions(test_fuzz PRIVATE CLIPS_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
  target_link_libraries(test_fuzz PRIVATE clips_data clips_lm GTest::gtest GTest::gtest_main)
  gtest_discover_tests(test_fuzz WORKING_DIRECTORY ${CMAKE_SOURCE_DIR} DISCOVERY_TIMEOUT 60
                       PROPERTIES TIMEOUT 120 LABELS unit)
  add_test(NAME FuzzSmoke COMMAND bash ${CMAKE_SOURCE_DIR}/fuzz/smoke.sh
           ${CMAKE_SOURCE_DIR}/build-fuzz ${CMAKE_SOURCE_DIR}/fuzz)
  set_tests_properties(FuzzSmoke PROPERTIES LABELS unit SKIP_RETURN_CODE 77 TIMEOUT 120)
endif()
