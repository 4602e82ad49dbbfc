# Common compile options for moorsph targets.
function(moorsph_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(MOORSPH_NATIVE AND CMAKE_BUILD_TYPE STREQUAL "Release")
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()

# Files that include Simbody headers must be compiled without NDEBUG: Debian built
# Simbody 3.7 without -DNDEBUG and some classes change layout with it (a Release
# build crashes in realizeTopology()). See DESIGN.md section 3.
function(moorsph_simbody_sources)
  set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS "-UNDEBUG")
endfunction()
