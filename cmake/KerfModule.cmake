# kerf_module(NAME PUBLIC_DEPS... [PRIVATE PRIVATE_DEPS...]): a static library from every .cpp in
# the calling folder and in its sub-folders that have no CMakeLists.txt of their own (csg/tape/,
# volume/octree/, ...: a module's sub-structure; io/plugin/ is a target of its own). A module
# with no sources yet is an interface library, so the tree still configures while a module is
# being written.
function(kerf_module name)
  cmake_parse_arguments(ARG "" "" "PRIVATE" ${ARGN})
  file(GLOB_RECURSE candidates CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  set(sources "")
  foreach(file IN LISTS candidates)
    # Walk up from the file's folder to the module's: a CMakeLists.txt on the way means the
    # file belongs to another target.
    get_filename_component(dir ${file} DIRECTORY)
    set(own TRUE)
    while(NOT dir STREQUAL CMAKE_CURRENT_SOURCE_DIR)
      if(EXISTS ${dir}/CMakeLists.txt)
        set(own FALSE)
        break()
      endif()
      get_filename_component(dir ${dir} DIRECTORY)
    endwhile()
    if(own)
      list(APPEND sources ${file})
    endif()
  endforeach()
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
