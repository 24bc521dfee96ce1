# Every dependency comes from Debian 12's packages (scripts/install-deps installs them).
find_package(glm REQUIRED)
find_package(TBB REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PkgConfig REQUIRED)
# OpenImageIO's CMake config names an OpenCV include folder that exists only when OpenCV is
# installed, so it is linked through its pkg-config file instead.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
find_package(Catch2 REQUIRED)
# OpenVDB ships its find module (not a config file) in its own folder.
list(APPEND CMAKE_MODULE_PATH /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB)
# Quietly: Debian 12's FindOpenVDB.cmake prints a stray "COMPONENT = openvdb", and the Imath
# config it loads names a Python module (libPyImath_Python3_11) that libimath-dev does not ship,
# printing a long "file does not exist" note; kerf uses neither. Errors still print.
set(_kerf_log_level "${CMAKE_MESSAGE_LOG_LEVEL}")
set(CMAKE_MESSAGE_LOG_LEVEL WARNING)
find_package(OpenVDB REQUIRED)
set(CMAKE_MESSAGE_LOG_LEVEL "${_kerf_log_level}")
unset(_kerf_log_level)
# Assimp reads mesh files (OBJ, PLY, STL, glTF) for mesh/ only; Debian's libassimp-dev ships a
# CMake config with the imported target assimp::assimp.
find_package(assimp REQUIRED)
# Text outlines (io/font_outline.cpp): FreeType reads the glyphs, fontconfig finds the files.
find_package(Freetype REQUIRED)
pkg_check_modules(FONTCONFIG REQUIRED IMPORTED_TARGET fontconfig)
