# The layers of fedsim's libraries, and the checks that keep them (configure time: a violation
# fails `cmake`, naming each offending link).
#
# Model libraries: the pure layer of fedsim (std, Eigen, GeographicLib, yaml-cpp; no DDS, no IDL
# types, no federate runtime, no wall clock). Every shared library in common/ (but the runtime
# layer's) and every federate's model/ folder is one.
#
#   fedsim_model_library(<target> <folder> [dependencies...])
#
# builds every <folder>/*.cpp into <target> (an INTERFACE library for header-only folders),
# links the dependencies PUBLIC, and builds <folder>/test/*_test.cpp into <target>_tests, run by
# CTest. The target is registered; fedsim_check_model_libraries() (called once at the end of the
# top-level CMakeLists.txt) then fails the configuration if any registered library links, even
# indirectly, one of FEDSIM_FORBIDDEN_IN_MODELS, or if one of its sources includes a DDS, IDL or
# runtime header. Models stay testable alone and usable in-process, in batch and in any federate.
#
# Rooms: each federate stands alone on common/. fedsim_check_rooms() (also called once at the
# end) places every target by its folder - common/ and idl/ (the shared libraries and the
# runtime layer), federates/<name>/ (that federate's room), tools/, bench/, tests/, examples/
# (the tools) - and fails the configuration where a link breaks one of these rules:
#   1. a library under common/ links only libraries under common/ and idl/; a model library of a
#      federate links only common/ libraries and its own federate's model libraries (no other
#      federate's model);
#   2. an adapter (any other library under federates/<name>/) links only its own federate's
#      libraries, common/ libraries and the runtime (fedsim_runtime, fedsim_idl);
#   3. nothing under federates/ (library, program or test) links a library under tools/, bench/,
#      tests/ or examples/.
# A federate's own programs and tests may compose other federates' adapters (a test flying the
# I/O and flight components together); a program that composes federates is a tool (tools/fly,
# tools/fedsim). Imported and system libraries are outside the rules. The links checked are each
# target's direct ones (LINK_LIBRARIES, INTERFACE_LINK_LIBRARIES): with every library checked,
# no chain of them can leave a room either.
#
# Model tests are labelled `unit` (cmake/FedsimTestLabels.cmake).

include(${CMAKE_CURRENT_LIST_DIR}/FedsimTestLabels.cmake)

set(FEDSIM_FORBIDDEN_IN_MODELS fastrtps fastcdr fedsim_idl fedsim_runtime)
# What a model source may not include (DDS headers, generated IDL types, the runtime).
set(FEDSIM_FORBIDDEN_MODEL_INCLUDES
    "#include[ \t]*[<\"](fastdds/|fastrtps/|fastcdr/|fedsim/msg/|common/runtime/)")

function(fedsim_model_library target folder)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/*.cpp)
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC ${CMAKE_SOURCE_DIR} ${CMAKE_SOURCE_DIR}/federates)
    target_link_libraries(${target} PUBLIC ${ARGN})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${CMAKE_SOURCE_DIR} ${CMAKE_SOURCE_DIR}/federates)
    target_link_libraries(${target} INTERFACE ${ARGN})
  endif()
  set_property(GLOBAL APPEND PROPERTY FEDSIM_MODEL_LIBRARIES ${target})
  set_property(GLOBAL PROPERTY FEDSIM_MODEL_FOLDER_${target} ${CMAKE_CURRENT_SOURCE_DIR}/${folder})

  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/test/*_test.cpp)
  if(tests AND TARGET GTest::gtest_main)
    add_executable(${target}_tests ${tests})
    target_link_libraries(${target}_tests PRIVATE ${target} fedsim_util fedsim_allocation_counter
                          GTest::gtest_main)
    fedsim_discover_tests(${target}_tests unit DISCOVERY_TIMEOUT 60)
  endif()
endfunction()

# What `target` links as CMake records it: LINK_LIBRARIES (but for an INTERFACE library) and
# INTERFACE_LINK_LIBRARIES, generator expressions and all.
function(_fedsim_linked target out_var)
  get_target_property(type ${target} TYPE)
  set(links "")
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(direct ${target} LINK_LIBRARIES)
    if(direct)
      list(APPEND links ${direct})
    endif()
  endif()
  get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
  if(interface)
    list(APPEND links ${interface})
  endif()
  set(${out_var} ${links} PARENT_SCOPE)
endfunction()

# The libraries `target` links, directly or through other targets (generator expressions such
# as $<LINK_ONLY:x> are unwrapped).
function(_fedsim_link_closure target out_var)
  set(seen "")
  set(queue ${target})
  while(queue)
    list(POP_FRONT queue item)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    if(item IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${item})
    if(TARGET ${item})
      _fedsim_linked(${item} links)
      list(APPEND queue ${links})
    endif()
  endwhile()
  list(REMOVE_ITEM seen ${target})
  set(${out_var} ${seen} PARENT_SCOPE)
endfunction()

function(fedsim_check_model_libraries)
  get_property(libraries GLOBAL PROPERTY FEDSIM_MODEL_LIBRARIES)
  set(problems "")
  foreach(library IN LISTS libraries)
    _fedsim_link_closure(${library} closure)
    foreach(forbidden IN LISTS FEDSIM_FORBIDDEN_IN_MODELS)
      if(forbidden IN_LIST closure)
        string(APPEND problems "\n  model library '${library}' links '${forbidden}'")
      endif()
    endforeach()
    get_property(folder GLOBAL PROPERTY FEDSIM_MODEL_FOLDER_${library})
    file(GLOB_RECURSE sources ${folder}/*.cpp ${folder}/*.hpp ${folder}/*.h)
    foreach(source IN LISTS sources)
      file(STRINGS ${source} hits REGEX "${FEDSIM_FORBIDDEN_MODEL_INCLUDES}")
      if(hits)
        list(GET hits 0 first)
        string(APPEND problems "\n  ${source}: ${first}")
      endif()
    endforeach()
  endforeach()
  if(problems)
    message(FATAL_ERROR "Model libraries must not use DDS, IDL types or the federate runtime "
                        "(put that in the federate's adapter):${problems}")
  endif()
  list(LENGTH libraries count)
  message(STATUS "fedsim: ${count} model libraries checked free of DDS, IDL and runtime")
endfunction()

# Temporary exceptions to the room rules, each "adapter->library": the instructor station and the
# scenario federate still link tools/topic (the typed flattener, topic replay) until those move
# to common/. These are the only ones; remove each when its link goes.
set(FEDSIM_ROOM_EXCEPTIONS
    "fedsim_ios_adapter->fedsim_topic_tools"
    "fedsim_scenario_adapter->fedsim_topic_tools")

# Where a target lives: "common" (common/, idl/), "federate:<name>" (federates/<name>/), "tool"
# (tools/, bench/, tests/, examples/), or "" (imported, a plain library name, or the top folder).
function(_fedsim_room_of target out_var)
  set(room "")
  if(TARGET ${target})
    get_target_property(aliased ${target} ALIASED_TARGET)
    if(aliased)
      set(target ${aliased})
    endif()
    get_target_property(imported ${target} IMPORTED)
    if(NOT imported)
      get_target_property(source_dir ${target} SOURCE_DIR)
      file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${source_dir})
      if(rel MATCHES "^(common|idl)(/|$)")
        set(room "common")
      elseif(rel MATCHES "^federates/([^/]+)")
        set(room "federate:${CMAKE_MATCH_1}")
      elseif(rel MATCHES "^(tools|bench|tests|examples)(/|$)")
        set(room "tool")
      endif()
    endif()
  endif()
  set(${out_var} "${room}" PARENT_SCOPE)
endfunction()

# The project targets `target` links directly ($<LINK_ONLY:x> unwrapped; other generator
# expressions and cross-directory markers skipped).
function(_fedsim_direct_links target out_var)
  _fedsim_linked(${target} links)
  set(out "")
  foreach(item IN LISTS links)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    if(item MATCHES "^(\\$<|::@)" OR NOT TARGET ${item})
      continue()
    endif()
    list(APPEND out ${item})
  endforeach()
  list(REMOVE_DUPLICATES out)
  set(${out_var} ${out} PARENT_SCOPE)
endfunction()

# The rule a link from `target` (in `room`, a model library or not) to `dependency` breaks, or "".
function(_fedsim_room_rule_broken target room is_model dependency out_var)
  _fedsim_room_of(${dependency} dep_room)
  get_property(models GLOBAL PROPERTY FEDSIM_MODEL_LIBRARIES)
  set(broken "")
  if(dep_room STREQUAL "" OR "${target}->${dependency}" IN_LIST FEDSIM_ROOM_EXCEPTIONS)
    # outside the rooms, or a stated exception
  elseif(room STREQUAL "common")
    if(NOT dep_room STREQUAL "common")
      set(broken "rule 1: common library '${target}' links '${dependency}' (${dep_room})")
    endif()
  elseif(room MATCHES "^federate:" AND dep_room STREQUAL "tool")
    set(broken "rule 3: '${target}' (${room}) links '${dependency}' (a tool)")
  elseif(room MATCHES "^federate:" AND is_model)
    if(NOT dep_room STREQUAL "common" AND NOT (dep_room STREQUAL room AND dependency IN_LIST models))
      set(broken "rule 1: model library '${target}' (${room}) links '${dependency}' (${dep_room})")
    endif()
  elseif(room MATCHES "^federate:")
    get_target_property(type ${target} TYPE)
    if(type MATCHES "LIBRARY" AND NOT dep_room STREQUAL "common" AND NOT dep_room STREQUAL room)
      set(broken "rule 2: adapter '${target}' (${room}) links '${dependency}' (${dep_room})")
    endif()
  endif()
  set(${out_var} "${broken}" PARENT_SCOPE)
endfunction()

function(fedsim_check_rooms)
  _fedsim_collect_targets(${CMAKE_SOURCE_DIR} all_targets)
  get_property(models GLOBAL PROPERTY FEDSIM_MODEL_LIBRARIES)
  set(problems "")
  set(checked 0)
  foreach(target IN LISTS all_targets)
    _fedsim_room_of(${target} room)
    get_target_property(type ${target} TYPE)
    if(room STREQUAL "" OR room STREQUAL "tool" OR type STREQUAL "UTILITY")
      continue()
    endif()
    math(EXPR checked "${checked} + 1")
    set(is_model OFF)
    if(target IN_LIST models)
      set(is_model ON)
    endif()
    _fedsim_direct_links(${target} links)
    foreach(dependency IN LISTS links)
      _fedsim_room_rule_broken(${target} ${room} ${is_model} ${dependency} broken)
      if(broken)
        string(APPEND problems "\n  ${broken}")
      endif()
    endforeach()
  endforeach()
  string(REPLACE ";" ", " exceptions "${FEDSIM_ROOM_EXCEPTIONS}")
  if(problems)
    message(FATAL_ERROR "Each federate depends only on common/ and the runtime (the rules at the top "
                        "of cmake/FedsimModel.cmake):${problems}\n"
                        "(the only exceptions, temporary: ${exceptions})")
  endif()
  message(STATUS "fedsim: ${checked} targets of common/ and federates/ checked: every federate stands "
                 "on common/ alone (temporary exceptions: ${exceptions})")
endfunction()

# Writes the library layers of the build as Graphviz DOT (build/fedsim_layers.dot): every
# library target of the project in its layer (shared pure libraries, the DDS runtime and IDL,
# federate models, federate adapters, tools) and the direct links between them. docs/images/
# layers.dot is a copy, checked by a test (so the architecture page stays the truth); the
# target `docs_images` redraws the pictures.
function(_fedsim_collect_targets dir out_var)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _fedsim_collect_targets(${sub} sub_targets)
    list(APPEND targets ${sub_targets})
  endforeach()
  set(${out_var} ${targets} PARENT_SCOPE)
endfunction()

function(fedsim_write_layers_dot file)
  _fedsim_collect_targets(${CMAKE_SOURCE_DIR} all_targets)
  get_property(models GLOBAL PROPERTY FEDSIM_MODEL_LIBRARIES)
  set(libraries "")
  foreach(t IN LISTS all_targets)
    get_target_property(type ${t} TYPE)
    if((type STREQUAL "STATIC_LIBRARY" OR type STREQUAL "INTERFACE_LIBRARY") AND
       NOT t MATCHES "allocation_counter|^gmock|^gtest")
      list(APPEND libraries ${t})
    endif()
  endforeach()
  list(SORT libraries)
  set(layer_common "")
  set(layer_runtime "")
  set(layer_models "")
  set(layer_adapters "")
  set(layer_tools "")
  foreach(t IN LISTS libraries)
    get_target_property(source_dir ${t} SOURCE_DIR)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${source_dir})
    if((t IN_LIST models AND rel MATCHES "^common") OR t STREQUAL "fedsim_util")
      list(APPEND layer_common ${t})
    elseif(t IN_LIST models)
      list(APPEND layer_models ${t})
    elseif(rel MATCHES "^(common|idl)")
      list(APPEND layer_runtime ${t})
    elseif(rel MATCHES "^federates")
      list(APPEND layer_adapters ${t})
    else()
      list(APPEND layer_tools ${t})
    endif()
  endforeach()
  set(dot "digraph fedsim_layers {\n  rankdir=BT;\n  node [shape=box, style=rounded, fontname=\"Helvetica\", fontsize=10];\n  edge [color=gray50, arrowsize=0.6];\n")
  foreach(layer IN ITEMS tools adapters runtime models common)
    if(layer STREQUAL "common")
      set(title "shared pure libraries (common/): no DDS")
    elseif(layer STREQUAL "models")
      set(title "federate models (federates/*/model): no DDS")
    elseif(layer STREQUAL "runtime")
      set(title "runtime and IDL (common/runtime, idl/): the only DDS layer")
    elseif(layer STREQUAL "adapters")
      set(title "federate adapters and programs (federates/*)")
    else()
      set(title "tools (tools/, bench/, tests/)")
    endif()
    string(APPEND dot "  subgraph cluster_${layer} {\n    label=\"${title}\"; fontname=\"Helvetica\"; style=dashed;\n")
    foreach(t IN LISTS layer_${layer})
      string(APPEND dot "    \"${t}\";\n")
    endforeach()
    string(APPEND dot "  }\n")
  endforeach()
  foreach(t IN LISTS libraries)
    _fedsim_linked(${t} links)
    list(REMOVE_DUPLICATES links)
    list(SORT links)
    foreach(l IN LISTS links)
      if(l IN_LIST libraries)
        string(APPEND dot "  \"${t}\" -> \"${l}\";\n")
      endif()
    endforeach()
  endforeach()
  string(APPEND dot "}\n")
  file(WRITE ${file} "${dot}")
endfunction()

# Writes the programs the build makes for users, one "name folder" a line: every executable
# target named `fedsim` or `fedsim-*` (test executables are named `*_tests`). The benchmarks
# (`fedsim-bench-*`) go to their own list. docs/programs.md and docs/benchmarks.md must name
# each one (tests/docs: Docs.ProgramsTableIsComplete, Docs.BenchmarksTableIsComplete).
function(fedsim_write_program_lists programs_file benchmarks_file)
  _fedsim_collect_targets(${CMAKE_SOURCE_DIR} all_targets)
  set(programs "")
  set(benchmarks "")
  foreach(t IN LISTS all_targets)
    get_target_property(type ${t} TYPE)
    if(NOT type STREQUAL "EXECUTABLE" OR NOT t MATCHES "^fedsim(-.+)?$")
      continue()
    endif()
    get_target_property(source_dir ${t} SOURCE_DIR)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${source_dir})
    if(t MATCHES "^fedsim-bench-")
      string(APPEND benchmarks "${t} ${rel}\n")
    else()
      string(APPEND programs "${t} ${rel}\n")
    endif()
  endforeach()
  file(WRITE ${programs_file} "${programs}")
  file(WRITE ${benchmarks_file} "${benchmarks}")
endfunction()
