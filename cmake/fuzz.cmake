# sfx_add_fuzzer(<name> <source> [LIBS <libraries>...]): a libFuzzer target fuzz_<name> built
# from tests/fuzz/<source>, and a CTest entry fuzz.<name> (label "fuzz") that replays its seed
# corpus, tests/fuzz/corpus/<name>/, once per file (-runs=0: no new inputs, so it is
# deterministic and fast). A crash, sanitizer report, leak or a run over -timeout fails it.
# Needs Clang with -DSFX_SANITIZE=fuzzer-no-link,address,undefined (tools/run_sanitizers.sh).
if(SFX_BUILD_FUZZERS AND NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "SFX_BUILD_FUZZERS needs Clang (libFuzzer); configure with -DCMAKE_CXX_COMPILER=clang++-14")
endif()
if(SFX_BUILD_FUZZERS AND NOT SFX_SANITIZE MATCHES "fuzzer")
  message(FATAL_ERROR "SFX_BUILD_FUZZERS needs -DSFX_SANITIZE=fuzzer-no-link,address,undefined so every library is instrumented")
endif()

set(SFX_FUZZ_CORPUS_DIR ${PROJECT_SOURCE_DIR}/tests/fuzz/corpus)
add_custom_target(sfx_fuzzers)

function(sfx_add_fuzzer name source)
  cmake_parse_arguments(FUZZ "" "" "LIBS" ${ARGN})
  add_executable(fuzz_${name} ${source})
  target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
  target_link_libraries(fuzz_${name} PRIVATE ${FUZZ_LIBS} sfx_warnings)
  add_dependencies(sfx_fuzzers fuzz_${name})
  if(NOT EXISTS ${SFX_FUZZ_CORPUS_DIR}/${name})
    message(FATAL_ERROR "fuzz target ${name} has no seed corpus at tests/fuzz/corpus/${name}/")
  endif()
  add_test(NAME fuzz.${name} COMMAND fuzz_${name} -runs=0 -timeout=10 ${SFX_FUZZ_CORPUS_DIR}/${name})
  set_tests_properties(fuzz.${name} PROPERTIES LABELS "fuzz" TIMEOUT 300)
endfunction()
