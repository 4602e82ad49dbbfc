# Wave theory utilities (issue 6, item 1): included from fluid/CMakeLists.txt.
target_sources(moorsph_fluid PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/dispersion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/airy_wave.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stokes2_wave.cpp
  ${CMAKE_CURRENT_LIST_DIR}/peregrine_breather.cpp)
target_link_libraries(moorsph_fluid PUBLIC Eigen3::Eigen)
