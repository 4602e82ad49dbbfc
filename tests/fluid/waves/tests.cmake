# Wave theory utilities (issue 6, item 1): included from tests/fluid/CMakeLists.txt.
moorsph_add_gtest(NAME test_wave_theory
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/test_dispersion.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_airy_stokes.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_peregrine_breather.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_piston_transfer.cpp
  LIBS moorsph_fluid
  LABELS fast)
