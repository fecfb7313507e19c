# Every dependency is a Debian 12 package (scripts/install-deps.sh installs them).
# The two fixes below are for packaging faults measured on Debian 12 (shared/research/toolchain.md).

find_package(Threads REQUIRED)
find_package(OpenMP REQUIRED)
find_package(pugixml 1.13 CONFIG REQUIRED)
find_package(assimp 5.2 CONFIG REQUIRED)
find_package(TinyGLTF 2.7 CONFIG REQUIRED)
find_package(tinyobjloader CONFIG REQUIRED)  # Debian 12: 2.0.0~rc10 (the callback API streams OBJ)
find_package(CLI11 2.1 CONFIG REQUIRED)

find_package(OpenImageIO 2.4 CONFIG REQUIRED)
# Debian's OpenImageIO target names /usr/include/opencv4, which no package it depends on installs.
get_target_property(_rt_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
list(FILTER _rt_oiio_includes EXCLUDE REGEX "opencv")
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_rt_oiio_includes}")

# Debian's OpenColorIOConfig.cmake computes an empty install prefix; pkg-config is correct.
find_package(PkgConfig REQUIRED)
pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO>=2.1)

if(RT_BUILD_TESTS)
  find_package(GTest 1.12 CONFIG REQUIRED)
endif()
if(RT_BUILD_BENCH)
  find_package(benchmark 1.7 CONFIG REQUIRED)
endif()
