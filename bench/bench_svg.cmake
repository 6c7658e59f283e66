# bench_svg: SVG icons in one process against librsvg (C API + Cairo) and
# resvg (node, bench/bench_svg_resvg.js); librsvg is skipped when missing.
pkg_check_modules(BENCH_SVG_RSVG IMPORTED_TARGET librsvg-2.0 cairo)
add_executable(bench_svg ${CMAKE_CURRENT_SOURCE_DIR}/bench_svg.c)
target_compile_options(bench_svg PRIVATE ${CG_WARNINGS})
target_compile_definitions(bench_svg PRIVATE CG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(bench_svg PRIVATE cg_static)
if(BENCH_SVG_RSVG_FOUND)
  target_compile_definitions(bench_svg PRIVATE CG_BENCH_HAVE_RSVG)
  target_link_libraries(bench_svg PRIVATE PkgConfig::BENCH_SVG_RSVG)
else()
  message(STATUS "bench_svg: librsvg (librsvg2-dev) not found, its row is skipped")
endif()
