# kerf_module(NAME PUBLIC_DEPS... [PRIVATE PRIVATE_DEPS...]): a static library from every .cpp in
# the calling folder. A module with no sources yet is an interface library, so the tree still
# configures while a module is being written.
function(kerf_module name)
  cmake_parse_arguments(ARG "" "" "PRIVATE" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(sources)
    add_library(${name} STATIC ${sources})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${ARG_UNPARSED_ARGUMENTS} PRIVATE ${ARG_PRIVATE})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARG_UNPARSED_ARGUMENTS})
  endif()
endfunction()
