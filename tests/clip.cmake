# Boolean operations checked against GEOS (area and point membership).  GEOS
# is used only here and in the benchmark; without it the test says it is skipped.
find_library(CG_GEOS_C_LIBRARY NAMES geos_c)
find_path(CG_GEOS_C_INCLUDE NAMES geos_c.h)
if(CG_GEOS_C_LIBRARY AND CG_GEOS_C_INCLUDE)
  add_executable(clip_geos ${CMAKE_CURRENT_LIST_DIR}/clip_geos.c)
  target_compile_options(clip_geos PRIVATE ${CG_WARNINGS})
  target_include_directories(clip_geos PRIVATE ${CG_GEOS_C_INCLUDE})
  target_link_libraries(clip_geos PRIVATE cg_static ${CG_GEOS_C_LIBRARY})
  add_test(NAME test_clip_geos COMMAND clip_geos)
  # every boolean result valid as GEOS judges OGC polygons
  add_executable(clip_valid ${CMAKE_CURRENT_LIST_DIR}/clip_valid.c)
  target_compile_options(clip_valid PRIVATE ${CG_WARNINGS})
  target_include_directories(clip_valid PRIVATE ${CG_GEOS_C_INCLUDE})
  target_link_libraries(clip_valid PRIVATE cg_static ${CG_GEOS_C_LIBRARY})
  add_test(NAME test_clip_valid COMMAND clip_valid)
else()
  cg_add_missing_peer_test(test_clip_geos "GEOS" libgeos-dev)
  cg_add_missing_peer_test(test_clip_valid "GEOS" libgeos-dev)
endif()

# Boolean operations when memory runs out: the test wraps the C library's
# allocation functions (GNU ld's --wrap) to make each of libcg's allocations
# fail in turn.
include(CheckCSourceCompiles)
set(CMAKE_REQUIRED_LINK_OPTIONS "-Wl,--wrap=malloc")
check_c_source_compiles("#include <stdlib.h>
void *__real_malloc(size_t); void *__wrap_malloc(size_t n) { return __real_malloc(n); }
int main(void) { free(malloc(1)); return 0; }" CG_LINKER_WRAPS)
unset(CMAKE_REQUIRED_LINK_OPTIONS)
if(CG_LINKER_WRAPS)
  add_executable(clip_oom ${CMAKE_CURRENT_LIST_DIR}/clip_oom.c)
  target_compile_options(clip_oom PRIVATE ${CG_WARNINGS})
  target_link_libraries(clip_oom PRIVATE cg_static)
  target_link_options(clip_oom PRIVATE -Wl,--wrap=malloc -Wl,--wrap=calloc -Wl,--wrap=realloc)
  add_test(NAME test_clip_oom COMMAND clip_oom)
else()
  message(STATUS "the linker has no --wrap: skipping test_clip_oom")
endif()

# Line clipping against exact rational clipping with GMP's mpq (libgmp-dev);
# without GMP the test reports itself skipped and names the package.
find_library(CG_GMP_LIBRARY NAMES gmp)
find_path(CG_GMP_INCLUDE NAMES gmp.h)
if(CG_GMP_LIBRARY AND CG_GMP_INCLUDE)
  add_executable(clip_line_exact ${CMAKE_CURRENT_LIST_DIR}/clip_line_exact.c)
  target_compile_options(clip_line_exact PRIVATE ${CG_WARNINGS})
  target_include_directories(clip_line_exact PRIVATE ${CG_GMP_INCLUDE})
  target_link_libraries(clip_line_exact PRIVATE cg_static ${CG_GMP_LIBRARY} m)
  add_test(NAME test_clip_line_exact COMMAND clip_line_exact)
else()
  cg_add_missing_peer_test(test_clip_line_exact "GMP" libgmp-dev)
endif()
