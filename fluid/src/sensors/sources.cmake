# Sensors: wave gauges (METHOD.md section 3), wall pressure probes (section 2) and
# velocity and packing probes.
target_sources(moorsph_fluid PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/wave_gauge.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pressure_probe.cpp
  ${CMAKE_CURRENT_LIST_DIR}/velocity_probe.cpp
  ${CMAKE_CURRENT_LIST_DIR}/packing_probe.cpp)
