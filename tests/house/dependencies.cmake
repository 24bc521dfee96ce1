# house/dependencies: the module graph the code has against the one CMake and the docs declare.
#   cmake -DKERF_SOURCE_DIR=<repo> -P tests/house/dependencies.cmake
#
# Rules (every one failing names the file and line or the table row to fix):
# 1. An edge A -> B is a production file of module A (A/**/*.cpp|h) with `#include "B/..."`.
# 2. CMake must declare it directly: some kerf_module(...) or target_link_libraries(...) call in
#    A/**/CMakeLists.txt names kerf_B (PUBLIC or PRIVATE). A transitive link does not count: it
#    vanishes when the module in between drops its own edge (volume/ once reached io/ only because
#    every executable links kerf_io). The exceptions are header-only headers listed in
#    KERF_HEADER_ONLY below, which need no library (the docs row must still name the module).
# 3. docs/architecture.md's "Modules and dependencies" table must declare it: the last column of
#    A's row, with (parenthesised) remarks removed, names B as a word. A module named there that no
#    include uses fails too (the table would be stale). `everything` declares every module.
# 4. The include graph has no cycle.
# 5. Third-party headers stay in their files (KERF_THIRD_PARTY below).
# tests/, bench/ and the image plug-in's own headers of other libraries are not production code
# of a module for rule 1 (io/plugin/ is io's).
cmake_minimum_required(VERSION 3.18)
if(NOT KERF_SOURCE_DIR)
  message(FATAL_ERROR "dependencies.cmake: pass -DKERF_SOURCE_DIR=<the repository>")
endif()
set(root ${KERF_SOURCE_DIR})
set(modules csg scene io volume mesh lang render slice accuracy app assets)
# "module:header" pairs: header-only value types a module may include without linking.
set(KERF_HEADER_ONLY "io:csg/profiles/profile_path.h")
# "include regex@allowed path regex" (paths relative to the repository).
set(KERF_THIRD_PARTY
  "^openvdb/@^volume/.*vdb_[^/]*\\.cpp$"
  "^OpenImageIO/@^io/plugin/"
  "^assimp/@^mesh/"
  "^mpi\\.h$@^app/mpi/"
  "^(ft2build\\.h|freetype/)@^io/font_outline\\.cpp$"
  "^fontconfig/@^io/font_lookup\\.cpp$"
  "^CLI/@^app/")

set(present "")
foreach(m IN LISTS modules)
  if(IS_DIRECTORY ${root}/${m})
    list(APPEND present ${m})
  endif()
endforeach()
set(failures 0)
macro(fail text)
  message("house/dependencies: ${text}")
  math(EXPR failures "${failures} + 1")
endmacro()

# --- The include graph (rules 1, 5). edges_<A> = modules A includes; where_<A>_<B> = first site.
foreach(m IN LISTS present)
  set(edges_${m} "")
  file(GLOB_RECURSE files RELATIVE ${root} ${root}/${m}/*.cpp ${root}/${m}/*.h)
  list(SORT files)
  foreach(f IN LISTS files)
    file(STRINGS ${root}/${f} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([a-z_]+)/([^\"]*)\"")
        set(to ${CMAKE_MATCH_1})
        set(header "${CMAKE_MATCH_1}/${CMAKE_MATCH_2}")
        if(NOT to STREQUAL m AND to IN_LIST present)
          if(NOT to IN_LIST edges_${m})
            list(APPEND edges_${m} ${to})
            set(where_${m}_${to} "${f} (#include \"${header}\")")
          endif()
          if(NOT "${m}:${header}" IN_LIST KERF_HEADER_ONLY)
            set(linked_${m}_${to} TRUE)
          endif()
        endif()
      elseif(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<([^>]*)>")
        set(header ${CMAKE_MATCH_1})
        foreach(rule IN LISTS KERF_THIRD_PARTY)
          string(FIND "${rule}" "@" bar)
          string(SUBSTRING "${rule}" 0 ${bar} pattern)
          math(EXPR after "${bar} + 1")
          string(SUBSTRING "${rule}" ${after} -1 allowed)
          if(header MATCHES "${pattern}" AND NOT f MATCHES "${allowed}")
            fail("${f} includes <${header}>, allowed only in files matching ${allowed}")
          endif()
        endforeach()
      endif()
    endforeach()
  endforeach()
endforeach()

# --- CMake's declared links (rule 2): every kerf_<module> named in a kerf_module() or
# target_link_libraries() call of the module's CMakeLists.txt files, comments removed.
foreach(m IN LISTS present)
  set(cmake_${m} "")
  file(GLOB_RECURSE lists ${root}/${m}/CMakeLists.txt)
  foreach(list_file IN LISTS lists)
    file(STRINGS ${list_file} raw)
    set(text "")
    foreach(line IN LISTS raw)
      string(REGEX REPLACE "#.*" "" line "${line}")
      string(APPEND text " ${line}")
    endforeach()
    string(REGEX MATCHALL "(kerf_module|target_link_libraries)[ \t]*\\([^)]*\\)" calls "${text}")
    foreach(call IN LISTS calls)
      string(REGEX MATCHALL "kerf_[a-z_]+" names "${call}")
      foreach(name IN LISTS names)
        string(REGEX REPLACE "^kerf_" "" dep "${name}")
        if(dep IN_LIST present AND NOT dep STREQUAL m)
          list(APPEND cmake_${m} ${dep})
        endif()
      endforeach()
    endforeach()
  endforeach()
  foreach(to IN LISTS edges_${m})
    if(linked_${m}_${to} AND NOT to IN_LIST cmake_${m})
      fail("${m} -> ${to} (${where_${m}_${to}}) but no ${m}/CMakeLists.txt links kerf_${to}")
    endif()
  endforeach()
endforeach()

# --- The docs table (rule 3): rows "| `m/` | `kerf_m` | holds | depends on |".
file(STRINGS ${root}/docs/architecture.md doc_lines)
foreach(line IN LISTS doc_lines)
  if(line MATCHES "^\\| `([a-z_]+)/` \\|.*\\|([^|]*)\\|[ \t]*$")
    set(m ${CMAKE_MATCH_1})
    set(cell " ${CMAKE_MATCH_2} ")
    # Remarks in parentheses (nested ones too) are not declarations.
    while(cell MATCHES "\\([^()]*\\)")
      string(REGEX REPLACE "\\([^()]*\\)" "" cell "${cell}")
    endwhile()
    set(docs_${m} "")
    set(docs_row_${m} TRUE)
    foreach(dep IN LISTS present)
      if(cell MATCHES "[^A-Za-z0-9_]${dep}[^A-Za-z0-9_]" OR cell MATCHES "[^A-Za-z0-9_]everything[^A-Za-z0-9_]")
        if(NOT dep STREQUAL m)
          list(APPEND docs_${m} ${dep})
        endif()
      endif()
    endforeach()
    if(NOT cell MATCHES "everything")
      foreach(dep IN LISTS docs_${m})
        if(NOT dep IN_LIST edges_${m})
          fail("docs/architecture.md: the ${m}/ row names ${dep}, but no ${m}/ file includes ${dep}/")
        endif()
      endforeach()
    endif()
  endif()
endforeach()
foreach(m IN LISTS present)
  if(NOT docs_row_${m})
    fail("docs/architecture.md: the module table has no row for ${m}/")
    continue()
  endif()
  foreach(to IN LISTS edges_${m})
    if(NOT to IN_LIST docs_${m})
      fail("${m} -> ${to} (${where_${m}_${to}}) but docs/architecture.md's ${m}/ row does not name ${to}")
    endif()
  endforeach()
endforeach()

# --- Cycles (rule 4): peel off modules that include no module left; any remainder is cyclic.
set(left ${present})
set(progress TRUE)
while(progress)
  set(progress FALSE)
  foreach(m IN LISTS left)
    set(sink TRUE)
    foreach(to IN LISTS edges_${m})
      if(to IN_LIST left)
        set(sink FALSE)
      endif()
    endforeach()
    if(sink)
      list(REMOVE_ITEM left ${m})
      set(progress TRUE)
    endif()
  endforeach()
endwhile()
if(left)
  foreach(m IN LISTS left)
    foreach(to IN LISTS edges_${m})
      if(to IN_LIST left)
        fail("cycle: ${m} -> ${to} (${where_${m}_${to}})")
      endif()
    endforeach()
  endforeach()
endif()

if(failures GREATER 0)
  message(FATAL_ERROR "house/dependencies: ${failures} violation(s)")
endif()
list(LENGTH present count)
message("house/dependencies: ${count} modules, every include edge declared in CMake and docs, no cycle")
