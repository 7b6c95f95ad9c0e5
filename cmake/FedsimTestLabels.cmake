# Test labels: every CTest test carries exactly one label, which says what the test needs and so
# which tests a run can choose (`ctest --preset unit`, `ctest --test-dir build -L integration`):
#
#   unit         no DDS, no federation, no browser; fast (the `unit` preset, under a minute)
#   integration  starts federates or DDS participants on 127.0.0.1, or flies a long closed-loop
#                run (the whole QTG guide, a federation's job in-process)
#   hosts        network namespaces (tests/hosts, the netns tests; root, else skipped)
#   browser      chromium (tests/browser)
#   security     DDS Security (tests/security)
#
# The test Tests.EveryTestHasOneLabel (tests/labels) fails the suite when a test has none, more
# than one, or another.
set(FEDSIM_TEST_LABELS unit integration hosts browser security)

function(_fedsim_check_test_label label)
  if(NOT label IN_LIST FEDSIM_TEST_LABELS)
    message(FATAL_ERROR "test label '${label}' is not one of: ${FEDSIM_TEST_LABELS}")
  endif()
endfunction()

# fedsim_discover_tests(<target> <label> [EXCEPT <label> <gtest filter> ...]
#                       [DISCOVERY_TIMEOUT <s>] [PROPERTIES ...])
#
# gtest_discover_tests(<target>) with every case labelled <label>, but the cases an EXCEPT filter
# matches (a GoogleTest filter: "QosProfiles.*:TopicHz.*"), which get that filter's label: one
# test program may hold in-process cases and cases that need DDS.
function(fedsim_discover_tests target label)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "DISCOVERY_TIMEOUT" "EXCEPT;PROPERTIES")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "fedsim_discover_tests(${target}): unknown ${arg_UNPARSED_ARGUMENTS}")
  endif()
  set(options "")
  if(arg_DISCOVERY_TIMEOUT)
    set(options DISCOVERY_TIMEOUT ${arg_DISCOVERY_TIMEOUT})
  endif()
  _fedsim_check_test_label(${label})
  set(excepted "")
  while(arg_EXCEPT)
    list(POP_FRONT arg_EXCEPT other filter)
    if(NOT filter)
      message(FATAL_ERROR "fedsim_discover_tests(${target}): EXCEPT ${other} needs a gtest filter")
    endif()
    _fedsim_check_test_label(${other})
    gtest_discover_tests(${target} ${options} TEST_FILTER "${filter}"
                         PROPERTIES ${arg_PROPERTIES} LABELS ${other})
    list(APPEND excepted "${filter}")
  endwhile()
  set(rest "")
  if(excepted)
    list(JOIN excepted ":" negative)
    set(rest TEST_FILTER "-${negative}")
  endif()
  gtest_discover_tests(${target} ${options} ${rest}
                       PROPERTIES ${arg_PROPERTIES} LABELS ${label})
endfunction()

# fedsim_label_tests(<label> <test>...)   labels tests this directory declared with add_test
# fedsim_label_tests(<label> ALL_OTHERS)  labels every one of them not labelled yet (the folder's
#                                         default: call it after the directory's last add_test)
function(fedsim_label_tests label)
  _fedsim_check_test_label(${label})
  set(tests ${ARGN})
  if(tests STREQUAL "ALL_OTHERS")
    get_directory_property(declared TESTS)
    set(tests "")
    foreach(test IN LISTS declared)
      get_test_property(${test} LABELS labels)
      if(NOT labels)
        list(APPEND tests ${test})
      endif()
    endforeach()
  endif()
  if(tests)
    set_tests_properties(${tests} PROPERTIES LABELS ${label})
  endif()
endfunction()
