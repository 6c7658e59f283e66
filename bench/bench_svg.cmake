# bench_svg: SVG icons in one process against librsvg (C API + Cairo) and
# resvg (node, bench/bench_svg_resvg.js); librsvg is skipped when missing.
pkg_check_modules(BENCH_SVG_RSVG IMPORTED_TARGET librsvg-2.0 cairo)
add_executable(bench_svg ${CMAKE_CURRENT_SOURCE_DIR}/bench_svg.c)
target_compile_options(bench_svg PRIVATE ${CG_WARNINGS})
target_compile_definitions(bench_svg PRIVATE CG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(bench_svg PRIVATE cg_static)
cg_bench_peer(bench_svg
              WHEN BENCH_SVG_RSVG_FOUND
              DEFINE CG_BENCH_HAVE_RSVG
              LINK PkgConfig::BENCH_SVG_RSVG
              MESSAGE "bench_svg: librsvg (librsvg2-dev) not found, its row is skipped")
