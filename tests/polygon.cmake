# Polygon geometry (cg/polygon.h) checked against GEOS: offsets against
# GEOSBufferWithStyle, rectangle clips and triangulations against GEOS's
# overlay and validity, open paths clipped against GEOSIntersection and
# GEOSDifference.  Without GEOS each test says it is skipped.
find_library(CG_POLYGON_GEOS_LIBRARY NAMES geos_c)
find_path(CG_POLYGON_GEOS_INCLUDE NAMES geos_c.h)
foreach(name clip_offset_geos clip_polygon_geos clip_lines_geos)
  if(CG_POLYGON_GEOS_LIBRARY AND CG_POLYGON_GEOS_INCLUDE)
    add_executable(${name} ${CMAKE_CURRENT_LIST_DIR}/${name}.c)
    target_compile_options(${name} PRIVATE ${CG_WARNINGS})
    target_include_directories(${name} PRIVATE ${CG_POLYGON_GEOS_INCLUDE})
    target_link_libraries(${name} PRIVATE cg_static ${CG_POLYGON_GEOS_LIBRARY} m)
    add_test(NAME test_${name} COMMAND ${name})
  else()
    cg_add_missing_peer_test(test_${name} "GEOS" libgeos-dev)
  endif()
endforeach()
