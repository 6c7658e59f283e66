# bench_polygon: offsets, rectangle clips and triangulations (cg/polygon.h)
# against Clipper2 2.0, built from ../shared/peers/clipper2 when it is there
# (benchmarks only: nothing of it goes into cg), and GEOS's buffer.
add_executable(bench_polygon ${CMAKE_CURRENT_LIST_DIR}/bench_polygon.c
                             ${CMAKE_CURRENT_LIST_DIR}/bench_polygon_peers.cpp)
target_compile_options(bench_polygon PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
target_link_libraries(bench_polygon PRIVATE cg_static m)
target_compile_definitions(bench_polygon PRIVATE CG_TOOL="$<TARGET_FILE:cg>")
set(CG_PEERS_DIR "" CACHE PATH "The peers' sources (../shared/peers of the main checkout)")
set(peer_dirs ${CG_PEERS_DIR} ${PROJECT_SOURCE_DIR}/../shared/peers
              ${PROJECT_SOURCE_DIR}/../../shared/peers)
set(clipper2 "")
foreach(dir ${peer_dirs})
  if(NOT clipper2 AND EXISTS ${dir}/clipper2/CPP/Clipper2Lib/include/clipper2/clipper.h)
    set(clipper2 ${dir}/clipper2/CPP/Clipper2Lib)
  endif()
endforeach()
if(clipper2)
  file(GLOB clipper2_sources ${clipper2}/src/clipper.*.cpp)
  target_sources(bench_polygon PRIVATE ${clipper2_sources})
  target_include_directories(bench_polygon PRIVATE ${clipper2}/include)
  target_compile_definitions(bench_polygon PRIVATE CG_HAVE_CLIPPER2)
else()
  message(STATUS "Clipper2 sources (../shared/peers/clipper2) not found: bench_polygon runs without them")
endif()
find_path(CG_POLYGON_GEOS_INCLUDE_BENCH NAMES geos_c.h)
find_library(CG_POLYGON_GEOS_LIBRARY_BENCH NAMES geos_c)
cg_bench_peer(bench_polygon
              WHEN CG_POLYGON_GEOS_INCLUDE_BENCH AND CG_POLYGON_GEOS_LIBRARY_BENCH
              DEFINE CG_HAVE_GEOS
              INCLUDE ${CG_POLYGON_GEOS_INCLUDE_BENCH}
              LINK ${CG_POLYGON_GEOS_LIBRARY_BENCH}
              MESSAGE "GEOS (libgeos-dev) not found: bench_polygon runs without it")
