# moorsph_add_gtest(NAME name SOURCES a.cpp b.cpp LIBS lib... LABELS fast|slow|stability|validation [TIMEOUT s])
# One GoogleTest executable registered as one CTest test with the given labels.
# `fast` is the default suite (README test command); the others are opt-in.
include(GoogleTest)
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
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    ENVIRONMENT "OMP_WAIT_POLICY=passive;MOORSPH_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
endfunction()
