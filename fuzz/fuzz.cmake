# Included by the top-level CMakeLists.txt. One libFuzzer target per input
# surface: fuzz/<name>_fuzz.cpp, with the library it exercises.
# CLIPS_FUZZ_SMOKE_TARGETS are the ones `make fuzz-build` (and so `make test`)
# builds for the FuzzSmoke run; the others need much more of the code base
# under clang + ASan and are built by `make fuzz` only (target fuzz_targets_all).
set(CLIPS_FUZZ_SMOKE_TARGETS sexpr pddl plan dataset goalset pack pack_roles cost_profiles quantified_goals utterance
    completions chat)
set(CLIPS_FUZZ_TARGETS ${CLIPS_FUZZ_SMOKE_TARGETS} serve stdio bench_merge)
set(clips_fuzz_lib_sexpr clips_pddl)
set(clips_fuzz_lib_pddl clips_pddl)
set(clips_fuzz_lib_plan clips_pddl)
set(clips_fuzz_lib_dataset clips_data)
set(clips_fuzz_lib_goalset clips_data)
set(clips_fuzz_lib_pack clips_domains_builtin)
set(clips_fuzz_lib_pack_roles clips_domains_builtin)
set(clips_fuzz_lib_cost_profiles clips_domains_builtin)
set(clips_fuzz_lib_quantified_goals clips_data)
set(clips_fuzz_lib_utterance clips_lm)
set(clips_fuzz_lib_completions clips_lm)
set(clips_fuzz_lib_chat clips_lm)
set(clips_fuzz_lib_serve clips_serve)
set(clips_fuzz_lib_stdio clips_serve)
set(clips_fuzz_lib_bench_merge clips_eval)

if(CLIPS_FUZZ)
  # The request handlers without the rest of clips_serve: not the HTTP front
  # end, and the scenes the session state shows (clips_scenes; not the
  # experiments, benchmarks and reports).
  add_library(clips_fuzz_serve STATIC ${CMAKE_SOURCE_DIR}/src/serve/service.cpp
              ${CMAKE_SOURCE_DIR}/src/serve/play_session.cpp ${CMAKE_SOURCE_DIR}/src/serve/text_scene.cpp
              ${CMAKE_SOURCE_DIR}/src/scenes/scenes.cpp
              ${CMAKE_BINARY_DIR}/web_assets.cpp)
  target_link_libraries(clips_fuzz_serve PUBLIC clips_engine clips_render clips_data)
  set(clips_fuzz_lib_serve clips_fuzz_serve)
  # The JSON-lines front end: the handlers and the front ends' file (the
  # HTTP server is a module of its own, src/serve/http/).
  add_library(clips_fuzz_stdio STATIC ${CMAKE_SOURCE_DIR}/src/serve/frontends.cpp)
  target_link_libraries(clips_fuzz_stdio PUBLIC clips_fuzz_serve)
  set(clips_fuzz_lib_stdio clips_fuzz_stdio)
  set(fuzz_bins)
  set(fuzz_smoke_bins)
  foreach(t ${CLIPS_FUZZ_TARGETS})
    add_executable(${t}_fuzz ${CMAKE_SOURCE_DIR}/fuzz/${t}_fuzz.cpp)
    target_include_directories(${t}_fuzz PRIVATE ${CMAKE_SOURCE_DIR})
    target_compile_definitions(${t}_fuzz PRIVATE CLIPS_LIBFUZZER)
    target_link_libraries(${t}_fuzz PRIVATE ${clips_fuzz_lib_${t}})
    target_link_options(${t}_fuzz PRIVATE -fsanitize=fuzzer)
    set_target_properties(${t}_fuzz PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
    list(APPEND fuzz_bins ${t}_fuzz)
    if(t IN_LIST CLIPS_FUZZ_SMOKE_TARGETS)
      list(APPEND fuzz_smoke_bins ${t}_fuzz)
    endif()
  endforeach()
  add_custom_target(fuzz_targets DEPENDS ${fuzz_smoke_bins})
  add_custom_target(fuzz_targets_all DEPENDS ${fuzz_bins})
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
  target_link_libraries(test_fuzz PRIVATE clips_data clips_lm clips_serve clips_eval GTest::gtest GTest::gtest_main)
  gtest_discover_tests(test_fuzz WORKING_DIRECTORY ${CMAKE_SOURCE_DIR} DISCOVERY_TIMEOUT 60
                       PROPERTIES TIMEOUT 120 LABELS unit ENVIRONMENT "CLIPS_LM_CACHE_DIR=${CMAKE_BINARY_DIR}/lm-cache")
  add_test(NAME FuzzSmoke COMMAND bash ${CMAKE_SOURCE_DIR}/fuzz/smoke.sh
           ${CMAKE_SOURCE_DIR}/build-fuzz ${CMAKE_SOURCE_DIR}/fuzz 2 ${CLIPS_FUZZ_SMOKE_TARGETS})
  # About 2 s per target plus start-up (the utterance target trains its
  # model under ASan): half a minute, so labelled slow, not unit.
  set_tests_properties(FuzzSmoke PROPERTIES LABELS slow SKIP_RETURN_CODE 77 TIMEOUT 120)
endif()
