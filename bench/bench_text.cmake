# bench_text: glyphs of a paragraph by cg against FreeType's smooth rasterizer
# on the same outlines (FreeType is a build dependency), and the paragraph
# through `cg draw --repeat`.
pkg_check_modules(BENCH_TEXT_FREETYPE REQUIRED IMPORTED_TARGET freetype2)
add_executable(bench_text ${CMAKE_CURRENT_SOURCE_DIR}/bench_text.c)
target_compile_options(bench_text PRIVATE ${CG_WARNINGS})
target_compile_definitions(bench_text PRIVATE CG_TOOL="$<TARGET_FILE:cg>" _POSIX_C_SOURCE=200809L
                                              _DEFAULT_SOURCE)
target_link_libraries(bench_text PRIVATE cg_static PkgConfig::BENCH_TEXT_FREETYPE m)
add_dependencies(bench_text cg)
