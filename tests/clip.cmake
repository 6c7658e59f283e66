# Boolean operations checked against GEOS (area and point membership).  GEOS
# is used only here and in the benchmark; without it the test is skipped.
find_library(CG_GEOS_C_LIBRARY NAMES geos_c)
find_path(CG_GEOS_C_INCLUDE NAMES geos_c.h)
if(CG_GEOS_C_LIBRARY AND CG_GEOS_C_INCLUDE)
  add_executable(clip_geos ${CMAKE_CURRENT_LIST_DIR}/clip_geos.c)
  target_compile_options(clip_geos PRIVATE ${CG_WARNINGS})
  target_include_directories(clip_geos PRIVATE ${CG_GEOS_C_INCLUDE})
  target_link_libraries(clip_geos PRIVATE cg_static ${CG_GEOS_C_LIBRARY})
  add_test(NAME test_clip_geos COMMAND clip_geos)
else()
  message(STATUS "GEOS (libgeos-dev) not found: skipping test_clip_geos")
endif()
