# Model libraries: the pure layer of fedsim (std, Eigen, GeographicLib, yaml-cpp; no DDS, no IDL
# types, no federate runtime, no wall clock). Every shared library in common/ (but the runtime)
# and every federate's model/ folder is one.
#
#   fedsim_model_library(<target> <folder> [dependencies...])
#
# builds every <folder>/*.cpp into <target> (an INTERFACE library for header-only folders),
# links the dependencies PUBLIC, and builds <folder>/test/*_test.cpp into <target>_tests, run by
# CTest. The target is registered; fedsim_check_model_libraries() (called once at the end of the
# top-level CMakeLists.txt) then fails the configuration if any registered library links, even
# indirectly, one of FEDSIM_FORBIDDEN_IN_MODELS, or if one of its sources includes a DDS, IDL or
# runtime header. Models stay testable alone and usable in-process, in batch and in any federate.

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
    target_link_libraries(${target}_tests PRIVATE ${target} fedsim_allocation_counter
                          GTest::gtest_main)
    target_compile_definitions(${target}_tests PRIVATE
      FEDSIM_TEST_DATA_DIR="${CMAKE_SOURCE_DIR}/tests/data")
    gtest_discover_tests(${target}_tests DISCOVERY_TIMEOUT 60)
  endif()
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
      get_target_property(type ${item} TYPE)
      set(links "")
      if(NOT type STREQUAL "INTERFACE_LIBRARY")
        get_target_property(direct ${item} LINK_LIBRARIES)
        if(direct)
          list(APPEND links ${direct})
        endif()
      endif()
      get_target_property(interface ${item} INTERFACE_LINK_LIBRARIES)
      if(interface)
        list(APPEND links ${interface})
      endif()
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
