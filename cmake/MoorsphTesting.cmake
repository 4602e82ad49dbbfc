# moorsph_add_gtest(NAME name SOURCES a.cpp b.cpp LIBS lib... LABELS fast|slow|stability|validation [TIMEOUT s])
# One GoogleTest executable registered as one CTest test with the given labels.
# `fast` is the default suite (README test command); the others are opt-in.
include(GoogleTest)

# moorsph_test_environment(OUT_VAR test_name): the environment every test runs with.
# TEST_TMPDIR (read by testing::TempDir()) is a directory of the test's own inside the
# build tree, so two suites run at once (two clones, or two build trees) never write
# into each other's /tmp/moorsph_* output.
function(moorsph_test_environment out_var test_name)
  set(tmp ${CMAKE_BINARY_DIR}/test_tmp/${test_name})
  file(MAKE_DIRECTORY ${tmp})
  set(${out_var} "OMP_WAIT_POLICY=passive;MOORSPH_SOURCE_DIR=${CMAKE_SOURCE_DIR};TEST_TMPDIR=${tmp}"
      PARENT_SCOPE)
endfunction()

function(moorsph_add_gtest)
  cmake_parse_arguments(T "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  if(NOT T_LABELS)
    set(T_LABELS fast)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  moorsph_target_defaults(${T_NAME})
  add_test(NAME ${T_NAME} COMMAND ${T_NAME} --gtest_color=no)
  moorsph_test_environment(environment ${T_NAME})
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    ENVIRONMENT "${environment}")
endfunction()
