# moorsph_add_gtest(NAME name SOURCES a.cpp b.cpp LIBS lib... LABELS fast|slow|stability|validation
#                   [TIMEOUT s] [THREADS n] [COST s])
# One GoogleTest executable registered as one CTest test with the given labels.
# `fast` is the default suite (README test command); the others are opt-in.
# The suite runs as `ctest -j<cores>` (scripts/test.sh): each test gets THREADS OpenMP threads
# (default 1) and reserves as many cores, so tests run side by side without oversubscribing;
# most tests are too small to gain from a second thread. COST (seconds on one CI core) makes
# CTest start the long tests first on a fresh build that has no timing history, so the
# suite does not end waiting on one long test.
include(GoogleTest)

# moorsph_test_environment(OUT_VAR test_name): the environment every test runs with.
# TEST_TMPDIR (read by testing::TempDir()) is a directory of the test's own inside the
# build tree, so two suites run at once (two clones, or two build trees) never write
# into each other's /tmp/moorsph_* output.
# OMP_NUM_THREADS: the test's share of the cores (optional third argument, default 1).
function(moorsph_test_environment out_var test_name)
  set(threads 1)
  if(ARGC GREATER 2)
    set(threads ${ARGV2})
  endif()
  set(tmp ${CMAKE_BINARY_DIR}/test_tmp/${test_name})
  file(MAKE_DIRECTORY ${tmp})
  set(${out_var}
      "OMP_WAIT_POLICY=passive;OMP_NUM_THREADS=${threads};MOORSPH_SOURCE_DIR=${CMAKE_SOURCE_DIR};TEST_TMPDIR=${tmp}"
      PARENT_SCOPE)
endfunction()

function(moorsph_add_gtest)
  cmake_parse_arguments(T "" "NAME;TIMEOUT;THREADS;COST" "SOURCES;LIBS;LABELS" ${ARGN})
  if(NOT T_LABELS)
    set(T_LABELS fast)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  if(NOT T_THREADS)
    set(T_THREADS 1)
  endif()
  if(NOT T_COST)
    set(T_COST 0)
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  moorsph_target_defaults(${T_NAME})
  add_test(NAME ${T_NAME} COMMAND ${T_NAME} --gtest_color=no)
  moorsph_test_environment(environment ${T_NAME} ${T_THREADS})
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    ENVIRONMENT "${environment}" PROCESSORS ${T_THREADS} COST ${T_COST})
endfunction()
