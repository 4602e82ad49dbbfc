# Wave theory utilities (issue 6, item 1): included from tests/fluid/CMakeLists.txt.
moorsph_add_gtest(NAME test_wave_theory
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/test_dispersion.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_airy_stokes.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_peregrine_breather.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_piston_transfer.cpp
    ${CMAKE_CURRENT_LIST_DIR}/test_wave_height_controller.cpp
  LIBS moorsph_fluid
  LABELS fast)
# Short 2D wave-tank runs (forcing region, damping zone, gauges) against theory.
if(TARGET moorsph_wave_tanks)
  moorsph_add_gtest(NAME test_wave_tanks
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_wave_tanks.cpp
    LIBS moorsph_wave_tanks
    LABELS fast
    COST 140)
endif()
# A free wave's period against the dispersion relation (about 25 CPU seconds).
if(TARGET moorsph_wave_tanks)
  moorsph_add_gtest(NAME test_wave_propagation
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_wave_propagation.cpp
    LIBS moorsph_wave_tanks
    LABELS slow)
endif()
# Issue 6's slower validation: 10 wavelengths at ~9 particles per height (~31 CPU minutes).
if(TARGET moorsph_wave_tanks)
  moorsph_add_gtest(NAME test_wave_propagation_10_wavelengths
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_wave_propagation_10_wavelengths.cpp
    LIBS moorsph_wave_tanks
    LABELS validation
    TIMEOUT 5400)
endif()
