# Fails when a quoted include points up a layer or across to the other program
# (docs/developer.md, "Layers"). Run as: cmake -DROOT=<tree> -P check_layers.cmake
#
# The table below lists the layers bottom to top. Each has its members (path prefixes: a folder
# with its trailing slash, or a file) and the layers below it that its files may include
# (besides their own layer). A file belongs to the layer of its longest matching prefix; every
# file of coupler_lib, fluid_app and dem_app must belong to one, and every .cpp must be named
# in its program's (or coupler_lib's) CMakeLists.txt: the source lists are explicit, so a file
# left out would silently not be built. A layer may name only layers declared before it, so
# the table itself has no cycle.
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT)
  message(FATAL_ERROR "check_layers.cmake: pass -DROOT=<source tree>")
endif()

set(layers "")
set(prefixes "")
# layer(NAME MEMBERS prefix... [MAY layer...])
function(layer name)
  cmake_parse_arguments(arg "" "" "MEMBERS;MAY" ${ARGN})
  foreach(below IN LISTS arg_MAY)
    if(NOT below IN_LIST layers)
      message(FATAL_ERROR "check_layers.cmake: layer ${name} names ${below}, which is not "
                          "declared below it")
    endif()
  endforeach()
  foreach(prefix IN LISTS arg_MEMBERS)
    set(layer_of_prefix_${prefix} ${name} PARENT_SCOPE)
  endforeach()
  set(may_${name} ${arg_MAY} PARENT_SCOPE)
  list(APPEND layers ${name})
  list(APPEND prefixes ${arg_MEMBERS})
  set(layers ${layers} PARENT_SCOPE)
  set(prefixes ${prefixes} PARENT_SCOPE)
endfunction()

# coupler_lib: one CMake target per folder (coupler_lib/CMakeLists.txt).
layer(coupler_lib/errors MEMBERS coupler_lib/errors.hpp coupler_lib/words.hpp)
layer(coupler_lib/geometry MEMBERS coupler_lib/geometry/ MAY coupler_lib/errors)
layer(coupler_lib/output MEMBERS coupler_lib/output/ MAY coupler_lib/errors)
layer(coupler_lib/scene MEMBERS coupler_lib/scene/
      MAY coupler_lib/errors coupler_lib/geometry coupler_lib/output)
layer(coupler_lib/coupling MEMBERS coupler_lib/coupling/
      MAY coupler_lib/errors coupler_lib/geometry coupler_lib/output coupler_lib/scene)
layer(coupler_lib/app MEMBERS coupler_lib/app/
      MAY coupler_lib/errors coupler_lib/geometry coupler_lib/output coupler_lib/scene
          coupler_lib/coupling)
set(coupler coupler_lib/errors coupler_lib/geometry coupler_lib/output coupler_lib/scene
            coupler_lib/coupling coupler_lib/app)

# fluid_app: one CMake target per folder (fluid_app/CMakeLists.txt); each may use any layer of
# coupler_lib. porous_field.hpp, the kernel's input that hlbm writes, belongs to the kernel.
layer(fluid_app/lattice MEMBERS fluid_app/lattice/ MAY ${coupler})
layer(fluid_app/kernel MEMBERS fluid_app/kernel/ fluid_app/porous_field.hpp
      MAY ${coupler} fluid_app/lattice)
layer(fluid_app/parallel MEMBERS fluid_app/parallel/ MAY ${coupler} fluid_app/lattice)
layer(fluid_app/boundary MEMBERS fluid_app/boundary/
      MAY ${coupler} fluid_app/lattice fluid_app/parallel)
layer(fluid_app/solver MEMBERS fluid_app/solver/
      MAY ${coupler} fluid_app/lattice fluid_app/kernel fluid_app/parallel fluid_app/boundary)
layer(fluid_app/forcing MEMBERS fluid_app/forcing/ MAY ${coupler} fluid_app/solver)
layer(fluid_app/hlbm MEMBERS fluid_app/hlbm/ MAY ${coupler} fluid_app/lattice fluid_app/kernel)
layer(fluid_app/analytic MEMBERS fluid_app/analytic/ MAY ${coupler})
layer(fluid_app/output MEMBERS fluid_app/output/ MAY ${coupler})
layer(fluid_app/validation MEMBERS fluid_app/validation/
      MAY ${coupler} fluid_app/analytic fluid_app/output)
layer(fluid_app/stability MEMBERS fluid_app/stability/ MAY ${coupler} fluid_app/output)
layer(fluid_app/run MEMBERS fluid_app/run/
      MAY ${coupler} fluid_app/lattice fluid_app/parallel fluid_app/solver fluid_app/forcing
          fluid_app/output fluid_app/validation fluid_app/stability)
layer(fluid_app/coupling MEMBERS fluid_app/coupling/
      MAY ${coupler} fluid_app/lattice fluid_app/kernel fluid_app/parallel fluid_app/solver
          fluid_app/forcing fluid_app/hlbm fluid_app/output fluid_app/run)
layer(fluid_app/main MEMBERS fluid_app/main.cpp MAY ${coupler} fluid_app/run fluid_app/coupling)

# dem_app: one CMake target per folder (dem_app/CMakeLists.txt); each may use any layer of
# coupler_lib. The loads layer is the three pairs of files at dem_app's root.
layer(dem_app/contact MEMBERS dem_app/contact/ MAY ${coupler})
layer(dem_app/lubrication MEMBERS dem_app/lubrication/ MAY ${coupler})
layer(dem_app/loads MEMBERS dem_app/external_load. dem_app/load_table. dem_app/load_routing.
      MAY ${coupler})
layer(dem_app/setup MEMBERS dem_app/setup/ MAY ${coupler} dem_app/contact dem_app/lubrication)
layer(dem_app/engine MEMBERS dem_app/engine/
      MAY ${coupler} dem_app/contact dem_app/lubrication dem_app/loads dem_app/setup)
layer(dem_app/output MEMBERS dem_app/output/ MAY ${coupler} dem_app/engine)
layer(dem_app/run MEMBERS dem_app/run/
      MAY ${coupler} dem_app/contact dem_app/setup dem_app/engine dem_app/output)
layer(dem_app/coupling MEMBERS dem_app/coupling/
      MAY ${coupler} dem_app/setup dem_app/engine dem_app/output dem_app/run)
layer(dem_app/main MEMBERS dem_app/main.cpp MAY ${coupler} dem_app/run dem_app/coupling)

# The layer of a path (its longest member prefix), "" when none.
function(layer_of path out)
  set(best "")
  set(best_length 0)
  foreach(prefix IN LISTS prefixes)
    string(FIND "${path}" "${prefix}" at)
    string(LENGTH "${prefix}" length)
    if(at EQUAL 0 AND length GREATER best_length)
      set(best ${layer_of_prefix_${prefix}})
      set(best_length ${length})
    endif()
  endforeach()
  set(${out} "${best}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE sources RELATIVE ${ROOT} ${ROOT}/coupler_lib/*.hpp ${ROOT}/coupler_lib/*.cpp
     ${ROOT}/fluid_app/*.hpp ${ROOT}/fluid_app/*.cpp ${ROOT}/dem_app/*.hpp ${ROOT}/dem_app/*.cpp)
set(problems 0)
set(checked 0)
foreach(src IN LISTS sources)
  layer_of(${src} from)
  if(from STREQUAL "")
    message(SEND_ERROR "${src}: in no layer; add its folder to check_layers.cmake, the "
                       "program's CMakeLists.txt and docs/developer.md")
    math(EXPR problems "${problems} + 1")
    continue()
  endif()
  if(src MATCHES "^([a-z_]+)/(.+\\.cpp)$")
    set(lists ${CMAKE_MATCH_1}/CMakeLists.txt)
    string(REPLACE "." "\\." listed "${CMAKE_MATCH_2}")
    set(text "")
    if(EXISTS ${ROOT}/${lists})
      file(READ ${ROOT}/${lists} text)
    endif()
    if(NOT text MATCHES "[ \t\n(]${listed}[ \t\n)]")
      message(SEND_ERROR "${src}: not in the source list of ${lists}")
      math(EXPR problems "${problems} + 1")
    endif()
  endif()
  file(STRINGS ${ROOT}/${src} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" target "${line}")
    math(EXPR checked "${checked} + 1")
    if(NOT target MATCHES "^(coupler_lib|fluid_app|dem_app|tools|tests)/")
      continue()  # a file next to the includer
    endif()
    layer_of(${target} to)
    if(to STREQUAL from OR (NOT to STREQUAL "" AND to IN_LIST may_${from}))
      continue()
    endif()
    string(REPLACE ";" " " allowed "${may_${from}}")
    message(SEND_ERROR "${src} includes \"${target}\": ${from} may include only its own layer "
                       "and: ${allowed}")
    math(EXPR problems "${problems} + 1")
  endforeach()
endforeach()
list(LENGTH sources files)
if(problems GREATER 0)
  message(FATAL_ERROR "${problems} file(s) or include(s) against the layers (${files} files)")
endif()
message(STATUS "layers respected: ${checked} includes in ${files} files")
