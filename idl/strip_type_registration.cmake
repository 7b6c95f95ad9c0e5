# Run after fastddsgen (cmake -DFILES="a.cxx;b.cxx" -P strip_type_registration.cmake).
#
# fastddsgen 2.3 with -typeobject makes every generated struct's default constructor call
# register<file>Types(), which looks up and re-adds the TypeObject of every type of that IDL
# file in Fast DDS's TypeObjectFactory (string-keyed maps): constructing one message cost more
# than sending it, and a federate constructs messages every frame (measured: 12% of a federate's
# CPU in a 9-federate lockstep). fedsim's topic tools register every type once, explicitly
# (tools/topic: register_all_idl_types), and the runtime does not announce TypeObjects, so the
# call is removed from the constructors. A file with no such call is an error: fastddsgen's
# output changed and this script must be looked at again.
# It also drops the run-dependent object hashes fastddsgen leaves in comments (see below).
foreach(file IN LISTS FILES)
  file(READ ${file} text)
  string(REGEX MATCHALL "\n[ \t]*// Just to register all known types\n[ \t]*register[A-Za-z0-9_]*Types\\(\\);" calls "${text}")
  list(LENGTH calls count)
  if(count EQUAL 0)
    message(FATAL_ERROR "${file}: no per-constructor type registration found (fastddsgen output changed?)")
  endif()
  string(REGEX REPLACE "\n[ \t]*// Just to register all known types\n[ \t]*register[A-Za-z0-9_]*Types\\(\\);" "" text "${text}")
  # The Java object hashes fastddsgen writes into comments ("EnumTypeCode@1dde4cb2") change
  # every run: without them the generated source is the same every time, and ccache serves it.
  string(REGEX REPLACE "(com\\.eprosima[A-Za-z.]*)@[0-9a-f]+" "\\1" text "${text}")
  file(WRITE ${file} "${text}")
endforeach()
