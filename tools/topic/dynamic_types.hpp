// Dynamic types for the topic tools: a topic's C++ type is not known at compile time, so the
// tools build a Fast DDS DynamicType from the TypeObjects that fedsim's generated code registers
// (fastddsgen -typeobject), looked up by the type name that discovery reports.
#pragma once

#include <fastrtps/types/DynamicTypePtr.h>
#include <fastrtps/types/TypeObject.h>

#include <string>

namespace fedsim::tools {

namespace ftypes = eprosima::fastrtps::types;

/// Registers the TypeObjects of every type in idl/*.idl with Fast DDS's TypeObjectFactory.
/// Idempotent and thread-safe; every lookup below calls it.
void register_fedsim_types();

/// The DynamicType of a registered type (complete TypeObject), e.g. "fedsim::msg::AircraftState";
/// null if no TypeObject of that name is known to this build.
ftypes::DynamicType_ptr dynamic_type_by_name(const std::string& type_name);

/// The DynamicType described by a TypeObject received in discovery (writers that send one);
/// null if it cannot be built (minimal objects carry no member names and are refused).
ftypes::DynamicType_ptr dynamic_type_from_object(const std::string& type_name,
                                                 const ftypes::TypeIdentifier& identifier,
                                                 const ftypes::TypeObject& object);

}  // namespace fedsim::tools
