# Wave theory utilities (issue 6, item 1): included from fluid/CMakeLists.txt.
# The FFT comes from Eigen's FFT module (header only, part of libeigen3-dev), so no new
# package is needed.
target_sources(moorsph_fluid PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/dispersion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/airy_wave.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stokes2_wave.cpp
  ${CMAKE_CURRENT_LIST_DIR}/peregrine_breather.cpp
  ${CMAKE_CURRENT_LIST_DIR}/piston_transfer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/piston_signal.cpp
  # Active amplitude correction of a wave maker (issue 6, item 5).
  ${CMAKE_CURRENT_LIST_DIR}/wave_height_controller.cpp)
target_link_libraries(moorsph_fluid PUBLIC Eigen3::Eigen)
